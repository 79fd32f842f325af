"""isaacsim.core.nodes.IsaacArticulationController on a recording fake world."""
import pytest

from graphflow.executor import GraphRuntimeError
from graphflow.testing import NodeHarness

from .fakes import FakeArticulationWorld

ARM = "/World/arm"
JOINTS = ("shoulder", "elbow", "wrist")
NAN = float("nan")


def _controller(**inputs):
    world = FakeArticulationWorld({ARM: JOINTS})
    return NodeHarness("isaacsim.core.nodes.IsaacArticulationController",
                       inputs={"robotPath": ARM, **inputs}, world=world), world


def test_all_joints_get_positions_in_dof_order():
    node, world = _controller(positionCommand=[0.1, -0.2, 0.3])
    assert node.compute("execIn").fired == {"execOut"}
    assert world.calls == [(ARM, (0, 1, 2), (0.1, -0.2, 0.3), None, None)]


def test_joint_names_select_and_order_the_joints():
    node, world = _controller(jointNames=["wrist", "shoulder"], velocityCommand=[1.5, -0.5])
    node.compute("execIn")
    assert world.calls == [(ARM, (2, 0), None, (1.5, -0.5), None)]


def test_joint_indices_including_zero_alone():
    node, world = _controller(jointIndices=[0], effortCommand=[12.0])
    node.compute("execIn")
    assert world.calls == [(ARM, (0,), None, None, (12.0,))]


def test_nan_leaves_that_joint_unchanged():
    node, world = _controller(positionCommand=[0.5, NAN, -0.5], velocityCommand=[NAN, NAN, NAN])
    node.compute("execIn")
    assert world.calls == [(ARM, (0, 2), (0.5, -0.5), None, None)]
    assert world.positions[ARM][1] == 0.0


def test_target_prim_is_used_when_robot_path_is_empty():
    world = FakeArticulationWorld({ARM: JOINTS})
    node = NodeHarness("isaacsim.core.nodes.IsaacArticulationController",
                       inputs={"targetPrim": ARM, "positionCommand": [1.0, 2.0, 3.0]}, world=world)
    node.compute("execIn")
    assert world.positions[ARM] == [1.0, 2.0, 3.0]


def test_length_mismatch_names_the_node_and_applies_nothing():
    node, world = _controller(positionCommand=[0.1, 0.2, 0.3], velocityCommand=[1.0, 2.0])
    with pytest.raises(GraphRuntimeError, match=r"node 'node': inputs:velocityCommand has 2 values for 3 joints"):
        node.compute("execIn")
    assert world.calls == []


def test_unknown_joint_name_is_an_error():
    node, world = _controller(jointNames=["knee"], positionCommand=[0.0])
    with pytest.raises(GraphRuntimeError, match="has no joint knee"):
        node.compute("execIn")
    assert world.calls == []


def test_no_robot_is_an_error():
    node = NodeHarness("isaacsim.core.nodes.IsaacArticulationController", world=FakeArticulationWorld({}))
    with pytest.raises(GraphRuntimeError, match="no robot prim"):
        node.compute("execIn")


def test_nothing_happens_without_a_pulse():
    node, world = _controller(positionCommand=[0.1, 0.2, 0.3])
    assert node.compute().fired == set()
    assert world.calls == []


def test_legacy_id_loads():
    node = NodeHarness("omni.isaac.core_nodes.IsaacArticulationController")
    assert node.database.spec.id == "isaacsim.core.nodes.IsaacArticulationController"
