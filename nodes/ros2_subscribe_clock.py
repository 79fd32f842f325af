"""isaacsim.ros2.bridge.ROS2SubscribeClock: the time of the newest rosgraph_msgs/Clock message."""
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState

from ._ros2 import common_inputs, seconds_of, take

SPEC = NodeSpec(
    id="isaacsim.ros2.bridge.ROS2SubscribeClock",
    version=1,
    aliases=("omni.isaac.ros2_bridge.ROS2SubscribeClock",),
    description=(
        "On execIn, takes the newest rosgraph_msgs/msg/Clock on topicName (default clock) and outputs its "
        "time in seconds; execOut fires when a new message was taken."),
    categories=("isaacRos2",),
    ui_name="ROS2 Subscribe Clock",
    inputs=common_inputs("clock", exec_description="Check for a new message"),
    outputs=(
        Attribute("execOut", "execution", description="Fires when a new message arrived"),
        Attribute("timeStamp", "double", description="The clock's time, s"),
    ),
)


def compute(db):
    if db.inputs.execIn != ExecState.ENABLED:
        return
    message = take(db, "rosgraph_msgs/msg/Clock")
    if message is None:
        return
    db.outputs.timeStamp = seconds_of(message["clock"])
    db.outputs.execOut = ExecState.ENABLED
