"""The robot demo graphs in graphs/, run headless to the end: where the cubes end up, and what was printed."""
import json
import math
from pathlib import Path

import pytest

from graphflow.document import dumps, load_document
from graphflow.runtime import Simulation

GRAPHS = Path(__file__).resolve().parents[2] / "graphs"
ROBOT_GRAPHS = ["ur10_pick_place.json", "ur10_pick_place_tuned.json", "ur10_stacking.json", "gantry_keyboard.json"]


def _run(name, seconds=60.0):
    simulation = Simulation.load(GRAPHS / name)
    result = simulation.run(seconds=seconds)
    return simulation, result


def _at_rest(world, prim):
    linear, angular = world.prim_velocity(prim)
    return math.hypot(*linear) < 1e-3 and math.hypot(*angular) < 1e-2


@pytest.mark.parametrize("name", [n for n in ROBOT_GRAPHS if (GRAPHS / n).exists()])
def test_graph_files_are_saved_in_canonical_form(name):
    path = GRAPHS / name
    assert dumps(load_document(path)) == path.read_text()


@pytest.mark.slow
def test_ur10_pick_place_places_the_cube_and_stops_by_itself():
    simulation, result = _run("ur10_pick_place.json")
    with simulation:
        world = simulation.world
        position, _ = world.prim_pose("/World/Cube")
        assert result.stopped_by_graph
        assert result.ticks == 1127                              # 1126 phase ticks, then done and the stop
        assert math.dist(position, (0.7, 0.7, 0.0515 / 2)) < 0.01
        assert _at_rest(world, "/World/Cube")
        logs = [event.message for event in simulation.instance.events]
        assert [line.split(":")[0] for line in logs[:-1]] == [
            "phase 0 move_above_pick", "phase 1 descend", "phase 2 settle", "phase 3 gripper_close", "phase 4 lift",
            "phase 5 move_to_place", "phase 6 descend_to_place", "phase 7 gripper_open",
            "phase 8 lift_after_place", "phase 9 hold_above_place", "phase 10 done"]
        assert logs[5] == "phase 5 move_to_place: gripper Closed"     # carried the whole way
        assert logs[8] == "phase 8 lift_after_place: gripper Open"
        assert logs[-1] == "pick and place done"


@pytest.mark.slow
def test_ur10_stacking_centres_the_top_cube_on_the_bottom_one():
    simulation, result = _run("ur10_stacking.json")
    with simulation:
        world = simulation.world
        bottom, _ = world.prim_pose("/World/Cube_0")
        top, _ = world.prim_pose("/World/Cube_1")
        assert result.stopped_by_graph
        assert math.dist(top[:2], bottom[:2]) < 0.01
        assert top[2] - bottom[2] == pytest.approx(0.05, abs=0.002)
        assert math.dist(bottom, (0.4, 0.4, 0.025)) < 0.01
        assert _at_rest(world, "/World/Cube_0") and _at_rest(world, "/World/Cube_1")
        logs = [event.message for event in simulation.instance.events]
        assert logs[3] == "cube 0 phase 3 gripper_close: gripper Closed"
        assert logs[13] == "cube 1 phase 3 gripper_close: gripper Closed"
        assert logs[-2:] == ["cube 2 phase 10 done: gripper Open", "stacking done"]
