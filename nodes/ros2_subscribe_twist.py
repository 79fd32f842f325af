"""isaacsim.ros2.bridge.ROS2SubscribeTwist: velocity commands from a geometry_msgs/Twist topic."""
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState

from ._ros2 import common_inputs, take

SPEC = NodeSpec(
    id="isaacsim.ros2.bridge.ROS2SubscribeTwist",
    version=1,
    aliases=("omni.isaac.ros2_bridge.ROS2SubscribeTwist",),
    description=(
        "On execIn, takes the newest geometry_msgs/msg/Twist on topicName (default cmd_vel) and outputs its "
        "linear (m/s) and angular (rad/s) velocity; execOut fires when a new message was taken."),
    categories=("isaacRos2",),
    ui_name="ROS2 Subscribe Twist",
    inputs=common_inputs("cmd_vel", exec_description="Check for a new message"),
    outputs=(
        Attribute("execOut", "execution", description="Fires when a new message arrived"),
        Attribute("linearVelocity", "vectord[3]", description="Linear velocity, m/s"),
        Attribute("angularVelocity", "vectord[3]", description="Angular velocity, rad/s"),
    ),
)


def compute(db):
    if db.inputs.execIn != ExecState.ENABLED:
        return
    message = take(db, "geometry_msgs/msg/Twist")
    if message is None:
        return
    db.outputs.linearVelocity = tuple(message["linear"][axis] for axis in "xyz")
    db.outputs.angularVelocity = tuple(message["angular"][axis] for axis in "xyz")
    db.outputs.execOut = ExecState.ENABLED
