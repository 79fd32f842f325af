"""The robot demo graphs in graphs/, run headless to the end: where the cubes end up, and what was printed."""
import json
import math

import pytest
from conftest import GRAPHS

from graphflow.document import dumps, load_document, parse_document
from graphflow.inputs.keyboard import attach_keyboard, scripted_keys
from graphflow.runtime import Simulation

ROBOT_GRAPHS = ["ur10_pick_place.json", "ur10_pick_place_tuned.json", "ur10_stacking.json", "gantry_keyboard.json",
                "panda_pick_place.json"]


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
        assert math.dist(position, (0.7, 0.7, 0.0515 / 2)) < 0.005
        assert _at_rest(world, "/World/Cube")
        logs = [event.message for event in simulation.instance.events]
        assert [line.split(":")[0] for line in logs[:-1]] == [
            "phase 0 move_above_pick", "phase 1 descend", "phase 2 settle", "phase 3 gripper_close", "phase 4 lift",
            "phase 5 move_to_place", "phase 6 descend_to_place", "phase 7 gripper_open",
            "phase 8 lift_after_place", "phase 9 hold_above_place", "phase 10 done"]
        assert logs[3] == "phase 3 gripper_close: gripper Closed"     # the close hits at once
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


@pytest.mark.slow
def test_gantry_keyboard_graph_carries_a_box_where_the_keys_say():
    simulation = Simulation.load(GRAPHS / "gantry_keyboard.json")
    attach_keyboard(simulation.world, scripted_keys(GRAPHS / "gantry_keyboard.keys.json"))
    with simulation:
        result = simulation.run(seconds=30.0)
        world = simulation.world
        box, orientation = world.prim_pose("/World/Boxes/Cube_28")
        assert result.stopped_by_graph and result.time == pytest.approx(14.0, abs=0.02)   # Escape@14
        assert [event.message for event in simulation.instance.events] == [
            "gripper Closed", "gripper Open", "Escape: stopping"]
        assert math.dist(box, (0.25, -0.25, 1.05)) < 0.01             # on the table (top 1.0), where told
        assert abs(orientation[2]) < 0.02                               # not spun on the way
        assert _at_rest(world, "/World/Boxes/Cube_28")
        targets = [world.get_attribute(f"/World/Joints/{joint}", "drive:linear:physics:targetPosition")
                   for joint in ("x_joint", "y_joint")]
        assert targets == pytest.approx([-0.25, 0.25], abs=1e-9)


@pytest.mark.slow
def test_gantry_drive_targets_stop_at_the_joint_limits():
    simulation = Simulation.load(GRAPHS / "gantry_keyboard.json")
    attach_keyboard(simulation.world, scripted_keys(None, ["Left@0.1-3.0", "PageUp@0.1-3.0", "Escape@3.1"]))
    with simulation:
        simulation.run(seconds=5.0)
        world = simulation.world
        x_target = world.get_attribute("/World/Joints/x_joint", "drive:linear:physics:targetPosition")
        z_target = world.get_attribute("/World/Joints/z_joint", "drive:linear:physics:targetPosition")
        assert x_target == pytest.approx(world.get_attribute("/World/Joints/x_joint", "physics:upperLimit"))
        assert z_target == pytest.approx(world.get_attribute("/World/Joints/z_joint", "physics:lowerLimit"))


def test_cli_runs_the_gantry_graph_with_key_flags(capsys):
    from graphflow.cli import main

    assert main(["run", str(GRAPHS / "gantry_keyboard.json"), "--key", "A@0.2", "--key", "Escape@0.5"]) == 0
    assert capsys.readouterr().out.splitlines()[-2:] == ["gripper Closing", "Escape: stopping"]


def test_cli_rejects_a_bad_key_flag(capsys):
    from graphflow.cli import main

    assert main(["run", str(GRAPHS / "gantry_keyboard.json"), "--key", "A@soon"]) == 2
    assert "expected KEY@TIME" in capsys.readouterr().err


@pytest.mark.slow
def test_ur10_pick_place_tuned_reports_the_grip_and_places_the_green_cube():
    simulation, result = _run("ur10_pick_place_tuned.json")
    with simulation:
        world = simulation.world
        position, _ = world.prim_pose("/World/Cube")
        assert result.stopped_by_graph
        assert [event.message for event in simulation.instance.events] == [
            "Gripper CLOSE command issued. Status: SUCCESS (Object Gripped)",
            "Gripper OPEN command issued. Status: Object Released",
            "Pick and Place routine has finished."]
        assert math.dist(position, (-0.4, 0.5, 0.025)) < 0.01      # placed at z 0.05: dropped 25 mm to the ground
        assert _at_rest(world, "/World/Cube")
        assert world.stage.GetPrimAtPath("/World/ur10/ee_link/SurfaceGripper_01").GetAttribute(
            "isaac:maxGripDistance").Get() == pytest.approx(0.02)


@pytest.mark.slow
def test_a_short_grip_threshold_misses_the_cube_and_says_so():
    data = json.loads((GRAPHS / "ur10_pick_place_tuned.json").read_text())
    next(n for n in data["nodes"] if n["name"] == "gripper")["inputs"]["gripThreshold"] = 0.002  # cup 5 mm above
    simulation = Simulation(parse_document(data, str(GRAPHS / "ur10_pick_place_tuned.json")))
    with simulation:
        simulation.run(seconds=30.0)
        position, _ = simulation.world.prim_pose("/World/Cube")
        assert [event.message for event in simulation.instance.events][0] == \
            "Gripper CLOSE command issued. Status: FAILURE (Missed Object)"
        assert math.dist(position[:2], (0.4, 0.4)) < 0.01
