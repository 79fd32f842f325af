"""isaacsim.ros2.bridge.ROS2SubscribeJointState: joint commands from a sensor_msgs/JointState topic.

execOut fires only on an execIn that finds a message this node has not taken
yet (the newest one), so a connected articulation controller commands once
per received message, as in Isaac.
"""
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState

from ._ros2 import common_inputs, seconds_of, take

SPEC = NodeSpec(
    id="isaacsim.ros2.bridge.ROS2SubscribeJointState",
    version=2,
    compatible_versions=(1,),
    aliases=("omni.isaac.ros2_bridge.ROS2SubscribeJointState",),
    description=(
        "On execIn, takes the newest sensor_msgs/msg/JointState on topicName (default joint_command) and "
        "outputs its joint names, position, velocity and effort commands and stamp; execOut fires when a new "
        "message was taken."),
    categories=("isaacRos2",),
    ui_name="ROS2 Subscribe Joint State",
    inputs=common_inputs("joint_command", exec_description="Check for a new message"),
    outputs=(
        Attribute("execOut", "execution", description="Fires when a new message arrived"),
        Attribute("jointNames", "token[]", description="Joint names of the message"),
        Attribute("positionCommand", "double[]", description="Position commands (rad or m)"),
        Attribute("velocityCommand", "double[]", description="Velocity commands (rad/s or m/s)"),
        Attribute("effortCommand", "double[]", description="Effort commands (N m or N)"),
        Attribute("timeStamp", "double", description="Stamp of the message, s"),
    ),
)


def compute(db):
    if db.inputs.execIn != ExecState.ENABLED:
        return
    message = take(db, "sensor_msgs/msg/JointState")
    if message is None:
        return
    db.outputs.jointNames = tuple(message["name"])
    db.outputs.positionCommand = tuple(message["position"])
    db.outputs.velocityCommand = tuple(message["velocity"])
    db.outputs.effortCommand = tuple(message["effort"])
    db.outputs.timeStamp = seconds_of(message["header"]["stamp"])
    db.outputs.execOut = ExecState.ENABLED
