"""isaacsim.ros2.bridge.ROS2PublishJointState on the example of Isaac Sim's own test (isaacsim.ros2.nodes
test_joint_state): an articulation driven to position targets (a revolute joint at -80 degrees, a prismatic one,
another revolute at 30 degrees) publishes them within Isaac's 1e-3 once it has moved there. Isaac's
SimpleArticulation is replaced by the packaged Panda (joint 1, finger joint 1, joint 7: no gravity load on them)."""
import math
import warnings
from pathlib import Path

import pytest

pytest.importorskip("rosbags")

from graphflow.physics import create_world  # noqa: E402
from graphflow.ros2.bus import topic_bus_for  # noqa: E402
from graphflow.testing import GraphHarness  # noqa: E402

PANDA = Path(__file__).resolve().parents[2] / "graphflow" / "assets" / "panda.usda"
TARGETS = {"panda_joint1": -80 * math.pi / 180, "panda_finger_joint1": 0.03, "panda_joint7": 30 * math.pi / 180}


def test_published_joint_states_reach_the_targets():
    graph = {"nodes": [
        {"name": "tick", "type": "omni.graph.action.OnPlaybackTick"},
        {"name": "drive", "type": "isaacsim.core.nodes.IsaacArticulationController",
         "inputs": {"robotPath": "/panda", "jointNames": list(TARGETS), "positionCommand": list(TARGETS.values())}},
        {"name": "time", "type": "isaacsim.core.nodes.IsaacReadSimulationTime"},
        {"name": "publish", "type": "isaacsim.ros2.bridge.ROS2PublishJointState", "inputs": {"targetPrim": ["/panda"]}}],
        "connections": [{"src": "tick.outputs:tick", "dst": "drive.inputs:execIn"},
                        {"src": "tick.outputs:tick", "dst": "publish.inputs:execIn"},
                        {"src": "time.outputs:simulationTime", "dst": "publish.inputs:timeStamp"}]}
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        world = create_world(str(PANDA), time_step=1.0 / 60.0)
    with world:
        harness = GraphHarness(graph, world=world)
        harness.run(120)
        message = topic_bus_for(world).published[-1]
    assert (message.topic, message.type) == ("/joint_states", "sensor_msgs/msg/JointState")
    state = message.message
    published = dict(zip(state["name"], state["position"]))
    assert {name: published[name] for name in TARGETS} == pytest.approx(TARGETS, abs=1e-3)
    assert state["header"]["stamp"] == {"sec": 2, "nanosec": 0}
