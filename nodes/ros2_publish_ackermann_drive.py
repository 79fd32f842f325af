"""isaacsim.ros2.bridge.ROS2PublishAckermannDrive: an ackermann_msgs/AckermannDriveStamped on every execIn."""
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState

from ._ros2 import common_inputs, header, publish

SPEC = NodeSpec(
    id="isaacsim.ros2.bridge.ROS2PublishAckermannDrive",
    version=1,
    description=(
        "Publishes ackermann_msgs/msg/AckermannDriveStamped on topicName (default ackermann_cmd): the header "
        "(timeStamp, frameId) and the drive command (steering angle and its rate, speed, acceleration, jerk)."),
    categories=("isaacRos2",),
    ui_name="ROS2 Publish AckermannDrive",
    inputs=common_inputs("ackermann_cmd", exec_description="Publish") + (
        Attribute("frameId", "string", default="", description="frame_id of the header"),
        Attribute("timeStamp", "double", default=0.0, description="Stamp of the header, s"),
        Attribute("steeringAngle", "double", default=0.0, description="Virtual front-axle wheel angle, rad"),
        Attribute("steeringAngleVelocity", "double", default=0.0, description="Its rate, rad/s"),
        Attribute("speed", "double", default=0.0, description="Forward speed, m/s"),
        Attribute("acceleration", "double", default=0.0, description="Acceleration, m/s^2"),
        Attribute("jerk", "double", default=0.0, description="Jerk, m/s^3"),
    ),
)


def compute(db):
    if db.inputs.execIn != ExecState.ENABLED:
        return
    inputs = db.inputs
    publish(db, "ackermann_msgs/msg/AckermannDriveStamped", {
        "header": header(inputs.timeStamp, inputs.frameId),
        "drive": {"steering_angle": inputs.steeringAngle, "steering_angle_velocity": inputs.steeringAngleVelocity,
                  "speed": inputs.speed, "acceleration": inputs.acceleration, "jerk": inputs.jerk}})
