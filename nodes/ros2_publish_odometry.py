"""isaacsim.ros2.bridge.ROS2PublishOdometry: nav_msgs/Odometry from a pose and velocities.

As Isaac's node: with publishRawVelocities the velocities go out as given;
otherwise each is projected onto the robot's axes: robotFront (its x and y,
normalised), the side up x front and the stage's up axis. Those axes are
fixed, not turned by orientation: the velocities a graph feeds
(IsaacComputeOdometry's) are already in the chassis frame, so the default
front (1, 0, 0) passes them through. Position and orientation go out as given.
Velocities are in m/s throughout graphflow (IsaacComputeOdometry gives metres),
so the stage-unit scaling Isaac applies here to its PhysX velocities is not
needed: the published message is the same.
"""
import math

from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState

from ._ros2 import common_inputs, header, publish, quaternion, vector

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
                  description="Publish the velocities as given instead of projected on the robot's axes"),
        Attribute("robotFront", "vectord[3]", default=(1.0, 0.0, 0.0),
                  description="The robot's front (x and y used; up is the stage's up axis)"),
        Attribute("timeStamp", "double", default=0.0, description="Message stamp, s"),
    ),
)


def compute(db):
    if db.inputs.execIn != ExecState.ENABLED:
        return
    inputs = db.inputs
    linear, angular = tuple(inputs.linearVelocity), tuple(inputs.angularVelocity)
    if not inputs.publishRawVelocities:
        axes = _robot_axes(db)
        linear, angular = _project(linear, axes), _project(angular, axes)
    publish(db, "nav_msgs/msg/Odometry", {
        "header": header(inputs.timeStamp, inputs.odomFrameId),
        "child_frame_id": inputs.chassisFrameId,
        "pose": {"pose": {"position": vector(inputs.position), "orientation": quaternion(inputs.orientation)}},
        "twist": {"twist": {"linear": vector(linear), "angular": vector(angular)}},
    })


def _robot_axes(db):
    """(front, side, up): robotFront flattened and normalised, the stage's up axis, side = up x front."""
    x, y = db.inputs.robotFront[0], db.inputs.robotFront[1]
    length = math.hypot(x, y)
    if length == 0.0:
        db.error("inputs:robotFront has no x or y component: no front to project the velocities on")
    front = (x / length, y / length, 0.0)
    up = (0.0, 1.0, 0.0) if _y_up(db.world) else (0.0, 0.0, 1.0)
    side = (up[1] * front[2] - up[2] * front[1], up[2] * front[0] - up[0] * front[2],
            up[0] * front[1] - up[1] * front[0])
    return front, side, up


def _project(vector_, axes):
    return tuple(sum(v * a for v, a in zip(vector_, axis)) for axis in axes)


def _y_up(world) -> bool:
    stage = getattr(world, "stage", None)
    if stage is None:
        return False
    from pxr import UsdGeom

    return UsdGeom.GetStageUpAxis(stage) == UsdGeom.Tokens.y
