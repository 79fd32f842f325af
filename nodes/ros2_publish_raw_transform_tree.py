"""isaacsim.ros2.bridge.ROS2PublishRawTransformTree: one given transform as tf2_msgs/TFMessage."""
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState

from ._ros2 import common_inputs, header, publish, quaternion, vector

SPEC = NodeSpec(
    id="isaacsim.ros2.bridge.ROS2PublishRawTransformTree",
    version=1,
    aliases=("omni.isaac.ros2_bridge.ROS2PublishRawTransformTree",),
    description=(
        "Publishes the transform translation/rotation from parentFrameId to childFrameId as a "
        "tf2_msgs/msg/TFMessage on topicName (default tf; tf_static with staticPublisher)."),
    categories=("isaacRos2",),
    ui_name="ROS2 Publish Raw Transform Tree",
    inputs=common_inputs("tf", exec_description="Publish") + (
        Attribute("parentFrameId", "string", default="odom", description="header.frame_id"),
        Attribute("childFrameId", "string", default="base_link", description="child_frame_id"),
        Attribute("translation", "vectord[3]", default=(0.0, 0.0, 0.0), description="Translation, m"),
        Attribute("rotation", "quatd[4]", default=(0.0, 0.0, 0.0, 1.0), description="Rotation (x, y, z, w)"),
        Attribute("staticPublisher", "bool", default=False,
                  description="Publish as a static transform (a latched topic in ROS; the bus keeps the latest)"),
        Attribute("timeStamp", "double", default=0.0, description="Message stamp, s"),
    ),
)


def compute(db):
    if db.inputs.execIn != ExecState.ENABLED:
        return
    inputs = db.inputs
    publish(db, "tf2_msgs/msg/TFMessage", {"transforms": [{
        "header": header(inputs.timeStamp, inputs.parentFrameId),
        "child_frame_id": inputs.childFrameId,
        "transform": {"translation": vector(inputs.translation), "rotation": quaternion(inputs.rotation)},
    }]})
