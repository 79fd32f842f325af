"""HolonomicRobotUsdSetup: a mecanum robot written as USD -> the setup -> HolonomicController -> wheel speeds.

The robot: a chassis at (1, 2, 0.1) m turned 90 degrees about z, four wheels at
(+-l, +-w) in the chassis frame, revolute joints about their frame's x axis
(localRot0 turns x onto the chassis y axis), rollers at +-45 degrees in an X
layout. Each wheel spinning at x rad/s pushes the chassis along
d = r * (its axis turned by its roller angle): FL and RR along (-1, 1)/sqrt2,
FR and RL along (1, 1)/sqrt2 (chassis frame). Isaac's controller asks for the
least-norm speeds whose pushes add up to (vx, vy) and, through d x p, to wz.
For this layout the three constraint rows are orthogonal, so by hand
x = sum_k b_k R_k / |R_k|^2 = (vx s1 + vy s2 + wz s3 / (l + w)) / (2 sqrt2 r),
s1 = (-1, 1, 1, -1), s2 = (1, 1, 1, 1), s3 = (-1, -1, 1, 1).
"""
import math

import pytest

from graphflow.executor import GraphRuntimeError
from graphflow.testing import ClockWorld, GraphHarness, NodeHarness

pxr = pytest.importorskip("pxr")

SETUP = "isaacsim.robot.wheeled_robots.HolonomicRobotUsdSetup"
L, W, R = 0.2, 0.15, 0.05     # half length, half width, wheel radius (m)
WHEELS = {"fl": (L, W, 45.0), "fr": (L, -W, -45.0), "rl": (-L, W, -45.0), "rr": (-L, -W, 45.0)}


def mecanum_stage(meters_per_unit=1.0):
    from pxr import Gf, Sdf, Usd, UsdGeom, UsdPhysics

    stage = Usd.Stage.CreateInMemory()
    UsdGeom.SetStageUpAxis(stage, UsdGeom.Tokens.z)
    UsdGeom.SetStageMetersPerUnit(stage, meters_per_unit)
    unit = 1.0 / meters_per_unit
    UsdGeom.Xform.Define(stage, "/World")
    robot = UsdGeom.Xform.Define(stage, "/World/robot")
    chassis = UsdGeom.Xform.Define(stage, "/World/robot/chassis")
    chassis.AddTranslateOp().Set(Gf.Vec3d(1.0 * unit, 2.0 * unit, 0.1 * unit))
    chassis.AddRotateZOp().Set(90.0)
    UsdPhysics.RigidBodyAPI.Apply(chassis.GetPrim())
    UsdPhysics.ArticulationRootAPI.Apply(robot.GetPrim())
    x_onto_y = Gf.Quatf(math.cos(math.pi / 4), 0.0, 0.0, math.sin(math.pi / 4))
    for name, (x, y, angle) in WHEELS.items():
        UsdGeom.Xform.Define(stage, f"/World/robot/{name}_wheel")
        joint = UsdPhysics.RevoluteJoint.Define(stage, f"/World/robot/chassis/{name}_joint")
        joint.CreateAxisAttr("X")
        joint.CreateBody0Rel().SetTargets(["/World/robot/chassis"])
        joint.CreateBody1Rel().SetTargets([f"/World/robot/{name}_wheel"])
        joint.CreateLocalPos0Attr(Gf.Vec3f(x * unit, y * unit, 0.0))
        joint.CreateLocalRot0Attr(x_onto_y)
        prim = joint.GetPrim()
        prim.CreateAttribute("isaacmecanumwheel:angle", Sdf.ValueTypeNames.Float).Set(angle)
        prim.CreateAttribute("isaacmecanumwheel:radius", Sdf.ValueTypeNames.Float).Set(R * unit)
    return stage


def stage_world(stage):
    world = ClockWorld()
    world.stage = stage
    return world


def hand_wheel_speeds(vx, vy, wz):
    s1, s2, s3 = (-1, 1, 1, -1), (1, 1, 1, 1), (-1, -1, 1, 1)
    return [(vx * a + vy * b + wz * c / (L + W)) / (2 * math.sqrt(2) * R) for a, b, c in zip(s1, s2, s3)]


def test_setup_reads_the_wheels_in_the_chassis_frame_in_metres():
    for meters_per_unit in (1.0, 0.01):
        world = stage_world(mecanum_stage(meters_per_unit))
        outputs = NodeHarness(SETUP, {"robotPrim": ["/World/robot"], "comPrim": ["/World/robot/chassis"]},
                              world=world).compute().outputs
        assert outputs["wheelDofNames"] == ("fl_joint", "fr_joint", "rl_joint", "rr_joint")
        assert outputs["wheelRadius"] == pytest.approx([R] * 4)
        assert outputs["mecanumAngles"] == pytest.approx([45.0, -45.0, -45.0, 45.0])
        expected_positions = [(x, y, 0.0) for x, y, _ in WHEELS.values()]
        for got, want in zip(outputs["wheelPositions"], expected_positions):
            assert got == pytest.approx(want, abs=1e-6)
        half = math.sqrt(0.5)
        for orientation in outputs["wheelOrientations"]:       # 90 degrees about z, (w, x, y, z)
            assert orientation == pytest.approx((half, 0.0, 0.0, half), abs=1e-6)
        assert outputs["wheelAxis"] == (1.0, 0.0, 0.0) and outputs["upAxis"] == (0.0, 0.0, 1.0)


@pytest.mark.parametrize("command", [(0.4, 0.0, 0.0), (0.0, 0.3, 0.0), (0.0, 0.0, 0.8), (0.2, -0.1, 0.5)])
def test_setup_feeds_the_controller_the_hand_computed_wheel_speeds(command):
    graph = GraphHarness({
        "nodes": [
            {"name": "tick", "type": "omni.graph.action.OnPlaybackTick"},
            {"name": "setup", "type": SETUP, "inputs": {"usePath": True, "robotPrimPath": "/World/robot",
                                                        "comPrimPath": "/World/robot/chassis"}},
            {"name": "controller", "type": "isaacsim.robot.wheeled_robots.HolonomicController",
             "inputs": {"inputVelocity": list(command)}},
        ],
        "connections": [{"src": "tick.outputs:tick", "dst": "controller.inputs:execIn"}] + [
            {"src": f"setup.outputs:{name}", "dst": f"controller.inputs:{name}"}
            for name in ("wheelRadius", "wheelPositions", "wheelOrientations", "mecanumAngles", "wheelAxis",
                         "upAxis")],
    }, world=stage_world(mecanum_stage()))
    graph.run(1)
    speeds = graph.output("controller", "jointVelocityCommand")
    assert speeds == pytest.approx(hand_wheel_speeds(*command), rel=1e-6, abs=1e-6)   # float32 authored frames


def test_setup_refuses_a_robot_without_mecanum_wheels_naming_the_prim():
    world = stage_world(mecanum_stage())
    with pytest.raises(GraphRuntimeError, match="no prim under /World/robot/fl_wheel has isaacmecanumwheel:angle"):
        NodeHarness(SETUP, {"robotPrim": ["/World/robot/fl_wheel"]}, world=world).compute()
    with pytest.raises(GraphRuntimeError, match="no prim /World/nothing"):
        NodeHarness(SETUP, {"usePath": True, "robotPrimPath": "/World/nothing"}, world=world).compute()
    with pytest.raises(GraphRuntimeError, match="no robot prim"):
        NodeHarness(SETUP, {}, world=world).compute()
    with pytest.raises(GraphRuntimeError, match="names no stage"):
        NodeHarness(SETUP, {"robotPrim": ["/World/robot"]}).compute()
