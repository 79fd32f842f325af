"""graphflow.PickPlaceSequence: tasks in order, each to a place position and yaw; the pyramid demo graph."""
import math

import pytest
from conftest import GRAPHS

from graphflow.document import GraphError, dumps, load_document, parse_document
from graphflow.runtime import Simulation
from graphflow_nodes.pick_place_sequence import shortest_turn, yaw_of

PYRAMID_PLACES = [(0.5, 0.245, 0.025), (0.5, 0.3, 0.025), (0.5, 0.355, 0.025),
                  (0.5, 0.2725, 0.075), (0.5, 0.3275, 0.075), (0.5, 0.3, 0.125)]


def sequence_graph(**inputs):
    return {"format": "graphflow", "formatVersion": [1, 0],
            "settings": {"stage": "asset:ur10_stacking.usda", "duration": 60.0},
            "nodes": [{"name": "on_tick", "type": "omni.graph.action.OnTick"},
                      {"name": "sequence", "type": "graphflow.PickPlaceSequence", "inputs": {
                          "robotPrim": "/World/ur10", "gripperPrim": "/World/ur10/ee_link/SurfaceGripper",
                          "objectPrims": ["/World/Cube_0", "/World/Cube_1"], "endEffectorOffset": [0, 0, 0.029],
                          **inputs}},
                      {"name": "stop", "type": "graphflow.StopRun"}],
            "connections": [{"src": "on_tick.outputs:tick", "dst": "sequence.inputs:execIn"},
                            {"src": "sequence.outputs:finished", "dst": "stop.inputs:execIn"}]}


def test_shortest_turn_uses_the_symmetry():
    assert shortest_turn(math.radians(100), math.pi / 2) == pytest.approx(math.radians(10))
    assert shortest_turn(math.radians(-80), math.pi / 2) == pytest.approx(math.radians(10))
    assert shortest_turn(math.radians(190), 0.0) == pytest.approx(math.radians(-170))
    assert yaw_of((0, 0, math.sin(0.3), math.cos(0.3))) == pytest.approx(0.6)


def test_mismatched_task_lists_are_refused_at_load():
    with pytest.raises(GraphError) as error:
        parse_document(sequence_graph(placePositions=[[0.4, 0.4, 0.025]]))
    assert "inputs:placePositions: 1 positions for 2 objectPrims" in str(error.value)
    with pytest.raises(GraphError) as error:
        parse_document(sequence_graph(placePositions=[[0.4, 0.4, 0.025], [0.4, 0.4, 0.075]], placeYaws=[0.1]))
    assert "inputs:placeYaws: 1 yaws for 2 placePositions" in str(error.value)


@pytest.mark.slow
def test_two_cubes_are_stacked_turned_to_their_place_yaws():
    document = parse_document(sequence_graph(placePositions=[[0.4, 0.4, 0.025], [0.4, 0.4, 0.075]],
                                             placeYaws=[0.5, -0.3], yawSymmetry=math.pi / 2))
    with Simulation(document) as simulation:
        result = simulation.run(seconds=60)
        assert result.stopped_by_graph and result.ticks == 2253      # two ten-phase tasks, back to back
        for prim, place, yaw in (("/World/Cube_0", (0.4, 0.4, 0.025), 0.5), ("/World/Cube_1", (0.4, 0.4, 0.075), -0.3)):
            position, orientation = simulation.world.prim_pose(prim)
            assert math.dist(position, place) < 0.002
            assert shortest_turn(yaw_of(orientation) - yaw, math.pi / 2) == pytest.approx(0.0, abs=0.01)


def test_pyramid_graph_is_saved_in_canonical_form():
    path = GRAPHS / "ur10_pyramid.json"
    assert dumps(load_document(path)) == path.read_text()


@pytest.mark.slow
def test_pyramid_graph_builds_the_3_2_1_pyramid():
    with Simulation.load(GRAPHS / "ur10_pyramid.json") as simulation:
        result = simulation.run(seconds=130)
        assert result.stopped_by_graph
        for index, place in enumerate(PYRAMID_PLACES):
            position, orientation = simulation.world.prim_pose(f"/World/Block_{index}")
            assert math.dist(position, place) < 0.003, (index, position)
            assert abs(shortest_turn(yaw_of(orientation), math.pi / 2)) < math.radians(2)
