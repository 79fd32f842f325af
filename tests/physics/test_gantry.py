"""Gantry stages: ours (graphflow/assets/gantry.usda) and Isaac Sim's own file, through the stage command."""
import json

import pytest
from conftest import ISAAC_GANTRY

from graphflow.cli.stage import run_stage_command
from graphflow.physics import create_world
from graphflow.usd.resolver import resolve_stage


def stage_json(capsys, path, seconds=None):
    assert run_stage_command(str(path), True, seconds) == 0
    return json.loads(capsys.readouterr().out)


def test_our_gantry_report(capsys):
    report = stage_json(capsys, resolve_stage("asset:gantry.usda"))
    assert len(report["rigid_bodies"]["dynamic"]) == 37
    assert report["joints"] == {"d6_attachment": 9, "fixed": 2, "prismatic": 3}
    assert report["articulations"][0]["movable_joints"] == ["/World/Joints/x_joint", "/World/Joints/y_joint",
                                                            "/World/Joints/z_joint"]
    gripper = report["surface_grippers"][0]
    assert gripper["path"] == "/World/SurfaceGripper" and len(gripper["attachment_points"]) == 9
    assert report["unsupported"] == []


def test_our_gantry_lowers_the_cones_to_9_9_mm_above_cube_28():
    with create_world("asset:gantry.usda") as world:
        world.set_attribute("/World/Joints/z_joint", "drive:linear:physics:targetPosition", 0.140)
        for _ in range(600):
            world.step()
        z = world.joint_positions("/World/Claw_base")[0]
        assert z == pytest.approx(0.140, abs=1e-3)
        cone_centre = world.prim_pose("/World/Surface_Gripper_Joints/D6Joint_04")[0]
        cube_top = world.prim_pose("/World/Boxes/Cube_28")[0][2] + 0.05
        assert cone_centre[2] == pytest.approx(1.5 - z - 0.15007, abs=1e-6)     # Isaac's geometry
        assert cone_centre[2] - cube_top == pytest.approx(0.0099, abs=1e-3)
        pitch = [world.prim_pose(f"/World/Surface_Gripper_Joints/D6Joint_0{i}")[0][0] for i in (3, 4, 5)]
        assert pitch[1] - pitch[0] == pytest.approx(0.0245, abs=1e-6)


@pytest.mark.slow
def test_isaac_gantry_stage_loads_and_rests(capsys):
    if not ISAAC_GANTRY.is_file():
        pytest.skip("Isaac Sim's gantry sample is not available next to the repository")
    report = stage_json(capsys, ISAAC_GANTRY, seconds=10.0)
    dynamic = report["rigid_bodies"]["dynamic"]
    assert len(dynamic) == 37
    assert report["joints"]["prismatic"] == 3 and report["joints"]["d6_attachment"] >= 9
    assert report["articulations"][0]["path"] == "/World/Claw_base"
    simulation = report["simulation"]
    boxes = {path: distance for path, distance in simulation["displacements"].items() if "/Boxes/" in path}
    assert len(boxes) == 32
    assert max(boxes.values()) < 0.005                                   # all 32 boxes rest
    assert report["max_displacement"]["distance"] < 0.005
    assert max(simulation["drive_errors"].values()) < 0.001              # gantry at its drive targets
    with create_world(ISAAC_GANTRY) as world:
        heights = sorted(round(world.prim_pose(path)[0][2], 3) for path in dynamic if "/Boxes/" in path)
    assert heights == [1.05] * 16 + [1.15] * 16                          # two layers


def test_stage_command_errors_are_one_line_exit_2(tmp_path, capsys):
    assert run_stage_command(str(tmp_path / "missing.usda"), False, None) == 2
    error = capsys.readouterr().err
    assert error.count("\n") == 1 and "missing.usda: no such stage file" in error
    assert run_stage_command(str(resolve_stage("asset:gantry.usda")), False, -1.0) == 2


def test_stage_command_human_output(capsys):
    assert run_stage_command(str(resolve_stage("asset:ur10_stacking.usda")), False, 0.5) == 0
    text = capsys.readouterr().out
    assert "articulations: 1" in text and "/World/ur10/ee_link/SurfaceGripper: 1 attachment points" in text
    assert "largest displacement of a free body: /World/Cube_" in text
