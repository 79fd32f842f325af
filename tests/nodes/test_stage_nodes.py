"""Stage nodes on a real PyBullet world, through graphflow.testing.harness."""
import pytest

from graphflow.physics import create_world
from graphflow.testing import GraphHarness, NodeHarness

Z_JOINT = "/World/Joints/z_joint"
Y_JOINT = "/World/Joints/y_joint"


@pytest.fixture()
def gantry():
    with create_world("asset:gantry.usda") as world:
        yield world


def test_read_prim_attribute_reads_limits_and_targets(gantry):
    node = NodeHarness("omni.graph.nodes.ReadPrimAttribute", {"prim": Z_JOINT, "name": "physics:upperLimit"},
                       world=gantry)
    assert node.compute().outputs["value"] == pytest.approx(0.2578865)
    node = NodeHarness("omni.graph.nodes.ReadPrimAttribute",
                       {"usePath": True, "primPath": Z_JOINT, "name": "drive:linear:physics:targetPosition"},
                       world=gantry)
    assert node.compute().outputs["value"] == 0.0


def test_write_prim_attribute_moves_the_drive_target(gantry):
    node = NodeHarness("omni.graph.nodes.WritePrimAttribute",
                       {"prim": Z_JOINT, "name": "drive:linear:physics:targetPosition", "value": 0.1}, world=gantry)
    assert node.compute("execIn").fired == {"execOut"}
    for _ in range(600):
        gantry.step()
    assert gantry.joint_positions(Z_JOINT)[0] == pytest.approx(0.1, abs=1e-3)


def test_unknown_attribute_is_a_node_error_naming_the_prim(gantry):
    node = NodeHarness("omni.graph.nodes.ReadPrimAttribute", {"prim": Z_JOINT, "name": "physics:nothing"},
                       world=gantry)
    with pytest.raises(Exception, match="z_joint has no attribute physics:nothing"):
        node.compute()


def test_read_prim_pose_and_joint_state(gantry):
    pose = NodeHarness("graphflow.ReadPrimPose", {"prim": "/World/Boxes/Cube_28"}, world=gantry).compute()
    assert pose.outputs["position"] == pytest.approx((0.0, 0.0, 1.15), abs=1e-6)
    assert pose.outputs["orientation"] == pytest.approx((0.0, 0.0, 0.0, 1.0), abs=1e-6)
    state = NodeHarness("graphflow.ReadJointState", {"prim": "/World/Gripper_Cones"}, world=gantry).compute()
    assert state.outputs["jointNames"] == ("z_joint", "x_joint", "y_joint")
    assert state.outputs["positions"] == pytest.approx((0.0, 0.0, 0.0))


def test_on_physics_step_fires_once_per_step_and_not_while_paused(gantry):
    node = NodeHarness("isaacsim.core.nodes.OnPhysicsStep", world=gantry)
    assert node.compute().fired == set()
    result = node.tick()
    assert result.fired == {"step"}
    assert result.outputs["deltaSimulationTime"] == pytest.approx(1 / 60)
    assert result.outputs["deltaSystemTime"] == result.outputs["deltaSimulationTime"]   # the run's clock
    assert result.outputs["simulationTime"] == pytest.approx(1 / 60)
    gantry.pause()
    assert node.tick().fired == set()


def test_clamped_keyboard_style_graph_drives_the_gantry_to_its_limit(gantry):
    """The gantry graph pattern: target += step each tick, clamped to the joint's upper limit (carriage along X)."""
    graph = {
        "nodes": [
            {"name": "tick", "type": "isaacsim.core.nodes.OnPhysicsStep"},
            {"name": "target", "type": "omni.graph.nodes.ReadPrimAttribute",
             "inputs": {"prim": Y_JOINT, "name": "drive:linear:physics:targetPosition"}},
            {"name": "upper", "type": "omni.graph.nodes.ReadPrimAttribute",
             "inputs": {"prim": Y_JOINT, "name": "physics:upperLimit"}},
            {"name": "step", "type": "omni.graph.nodes.ConstantDouble", "inputs": {"value": 0.01}},
            {"name": "add", "type": "omni.graph.nodes.Add"},
            {"name": "clamp", "type": "omni.graph.nodes.Minimum"},
            {"name": "write", "type": "omni.graph.nodes.WritePrimAttribute",
             "inputs": {"prim": Y_JOINT, "name": "drive:linear:physics:targetPosition"}},
        ],
        "connections": [{"src": src, "dst": dst} for src, dst in (
            ("tick.outputs:step", "write.inputs:execIn"),
            ("target.outputs:value", "add.inputs:a"),
            ("step.outputs:value", "add.inputs:b"),
            ("add.outputs:sum", "clamp.inputs:a"),
            ("upper.outputs:value", "clamp.inputs:b"),
            ("clamp.outputs:minimum", "write.inputs:value"),
        )],
    }
    harness = GraphHarness(graph, world=gantry)
    harness.run(ticks=600)
    assert gantry.get_attribute(Y_JOINT, "drive:linear:physics:targetPosition") == pytest.approx(0.45)
    dof = gantry.joint_names(Y_JOINT).index("y_joint")
    assert gantry.joint_positions(Y_JOINT)[dof] == pytest.approx(0.45, abs=1e-3)
    assert harness.output("clamp", "minimum") == pytest.approx(0.45)


def test_is_prim_active_and_get_prim_relationship_read_the_stage():
    from pxr import Usd

    from graphflow.executor import GraphRuntimeError
    from graphflow.testing.fake_world import FakeWorld

    stage = Usd.Stage.CreateInMemory()
    stage.DefinePrim("/World/On")
    stage.DefinePrim("/World/Off").SetActive(False)
    stage.DefinePrim("/World/Gripper").CreateRelationship("grips").SetTargets(["/World/On", "/World/Off"])
    world = FakeWorld(stage=stage)

    def out(type_id, output, **inputs):
        return NodeHarness(f"omni.graph.nodes.{type_id}", inputs, world=world).compute().outputs[output]

    assert out("IsPrimActive", "active", primTarget=["/World/On"]) is True
    assert out("IsPrimActive", "active", prim="/World/Off") is False
    assert out("GetPrimRelationship", "paths", path="/World/Gripper", name="grips") == ("/World/On", "/World/Off")
    with pytest.raises(GraphRuntimeError, match="has no relationship 'holds'"):
        out("GetPrimRelationship", "paths", path="/World/Gripper", name="holds")
