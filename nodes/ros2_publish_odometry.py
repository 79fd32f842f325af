"""isaacsim.ros2.bridge.ROS2PublishOdometry: nav_msgs/Odometry from a pose and velocities.

With publishRawVelocities the velocities go out as given; otherwise they are
turned into the chassis frame (the inverse of orientation), as ROS expects
Odometry's twist in child_frame_id.
"""
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState

from ._ros2 import common_inputs, header, publish, quaternion, rotate_into, vector

SPEC = NodeSpec(
    id="isaacsim.ros2.bridge.ROS2PublishOdometry",
    version=1,
    aliases=("omni.isaac.ros2_bridge.ROS2PublishOdometry",),
    description=(
        "Publishes nav_msgs/msg/Odometry (pose in odomFrameId, twist in chassisFrameId) on topicName "
        "(default odom)."),
    categories=("isaacRos2",),
    ui_name="ROS2 Publish Odometry",
    inputs=common_inputs("odom", exec_description="Publish") + (
        Attribute("chassisFrameId", "string", default="base_link", description="child_frame_id"),
        Attribute("odomFrameId", "string", default="odom", description="header.frame_id"),
        Attribute("position", "vectord[3]", default=(0.0, 0.0, 0.0), description="Position in the odometry frame, m"),
        Attribute("orientation", "quatd[4]", default=(0.0, 0.0, 0.0, 1.0), description="Orientation (x, y, z, w)"),
        Attribute("linearVelocity", "vectord[3]", default=(0.0, 0.0, 0.0), description="Linear velocity, m/s"),
        Attribute("angularVelocity", "vectord[3]", default=(0.0, 0.0, 0.0), description="Angular velocity, rad/s"),
        Attribute("publishRawVelocities", "bool", default=False,
                  description="Publish the velocities as given instead of in the chassis frame"),
        Attribute("timeStamp", "double", default=0.0, description="Message stamp, s"),
    ),
)


def compute(db):
    if db.inputs.execIn != ExecState.ENABLED:
        return
    inputs = db.inputs
    linear, angular = inputs.linearVelocity, inputs.angularVelocity
    if not inputs.publishRawVelocities:
        linear, angular = rotate_into(inputs.orientation, linear), rotate_into(inputs.orientation, angular)
    publish(db, "nav_msgs/msg/Odometry", {
        "header": header(inputs.timeStamp, inputs.odomFrameId),
        "child_frame_id": inputs.chassisFrameId,
        "pose": {"pose": {"position": vector(inputs.position), "orientation": quaternion(inputs.orientation)}},
        "twist": {"twist": {"linear": vector(linear), "angular": vector(angular)}},
    })
