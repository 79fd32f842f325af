"""isaacsim.ros2.bridge.ROS2PublishClock: rosgraph_msgs/Clock on every execIn."""
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState

from ._ros2 import common_inputs, publish

SPEC = NodeSpec(
    id="isaacsim.ros2.bridge.ROS2PublishClock",
    version=1,
    aliases=("omni.isaac.ros2_bridge.ROS2PublishClock",),
    description="Publishes timeStamp (simulated seconds) as rosgraph_msgs/msg/Clock on topicName (default clock).",
    categories=("isaacRos2",),
    ui_name="ROS2 Publish Clock",
    inputs=common_inputs("clock", exec_description="Publish") + (
        Attribute("timeStamp", "double", default=0.0, description="Time to publish, s (connect IsaacReadSimulationTime)"),
    ),
)


def compute(db):
    if db.inputs.execIn != ExecState.ENABLED:
        return
    from graphflow.ros2.messages import stamp

    publish(db, "rosgraph_msgs/msg/Clock", {"clock": stamp(db.inputs.timeStamp)})
