"""isaacsim.ros2.bridge.ROS2PublishImu: sensor_msgs/Imu from IMU readings.

A part left out (publishOrientation false, ...) has covariance[0] = -1, the
ROS convention for "no estimate".
"""
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState

from ._ros2 import common_inputs, header, publish, quaternion, vector

NO_ESTIMATE = [-1.0] + [0.0] * 8

SPEC = NodeSpec(
    id="isaacsim.ros2.bridge.ROS2PublishImu",
    version=1,
    aliases=("omni.isaac.ros2_bridge.ROS2PublishImu",),
    description=(
        "Publishes sensor_msgs/msg/Imu (orientation, angular velocity rad/s, linear acceleration m/s^2 in "
        "frameId) on topicName (default imu); connect IsaacReadIMU."),
    categories=("isaacRos2",),
    ui_name="ROS2 Publish Imu",
    inputs=common_inputs("imu", exec_description="Publish") + (
        Attribute("frameId", "string", default="sim_imu", description="header.frame_id"),
        Attribute("orientation", "quatd[4]", default=(0.0, 0.0, 0.0, 1.0), description="Orientation (x, y, z, w)"),
        Attribute("angularVelocity", "vectord[3]", default=(0.0, 0.0, 0.0), description="Angular velocity, rad/s"),
        Attribute("linearAcceleration", "vectord[3]", default=(0.0, 0.0, 0.0), description="Linear acceleration, m/s^2"),
        Attribute("publishOrientation", "bool", default=True, description="Include the orientation"),
        Attribute("publishAngularVelocity", "bool", default=True, description="Include the angular velocity"),
        Attribute("publishLinearAcceleration", "bool", default=True, description="Include the linear acceleration"),
        Attribute("timeStamp", "double", default=0.0, description="Message stamp, s"),
    ),
)


def compute(db):
    if db.inputs.execIn != ExecState.ENABLED:
        return
    inputs = db.inputs
    message = {"header": header(inputs.timeStamp, inputs.frameId)}
    for flag, field, value in (("publishOrientation", "orientation", quaternion(inputs.orientation)),
                               ("publishAngularVelocity", "angular_velocity", vector(inputs.angularVelocity)),
                               ("publishLinearAcceleration", "linear_acceleration", vector(inputs.linearAcceleration))):
        if getattr(inputs, flag):
            message[field] = value
        else:
            message[f"{field}_covariance"] = NO_ESTIMATE
    publish(db, "sensor_msgs/msg/Imu", message)
