"""isaacsim.ros2.bridge.ROS2SubscribeAckermannDrive: drive commands from an AckermannDriveStamped topic."""
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState

from ._ros2 import common_inputs, seconds_of, take

SPEC = NodeSpec(
    id="isaacsim.ros2.bridge.ROS2SubscribeAckermannDrive",
    version=1,
    description=(
        "On execIn, takes the newest ackermann_msgs/msg/AckermannDriveStamped on topicName (default "
        "ackermann_cmd): its header and drive command; execOut fires when a new message was taken."),
    categories=("isaacRos2",),
    ui_name="ROS2 Subscribe AckermannDrive",
    inputs=common_inputs("ackermann_cmd", exec_description="Check for a new message"),
    outputs=(
        Attribute("execOut", "execution", description="Fires when a new message arrived"),
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
    message = take(db, "ackermann_msgs/msg/AckermannDriveStamped")
    if message is None:
        return
    outputs, drive = db.outputs, message["drive"]
    outputs.frameId = message["header"]["frame_id"]
    outputs.timeStamp = seconds_of(message["header"]["stamp"])
    outputs.steeringAngle, outputs.steeringAngleVelocity = drive["steering_angle"], drive["steering_angle_velocity"]
    outputs.speed, outputs.acceleration, outputs.jerk = drive["speed"], drive["acceleration"], drive["jerk"]
    outputs.execOut = ExecState.ENABLED
