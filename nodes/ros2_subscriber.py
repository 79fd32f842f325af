"""isaacsim.ros2.bridge.ROS2Subscriber: any standard ROS 2 message type, received as JSON.

Isaac makes one dynamic output per message field; graphflow's node declares
its ports in one place, so the whole message comes out as one JSON object in
``message`` (every field present, defaults filled). Until the first message
arrives it holds the type's defaults, as Kit's field outputs hold theirs.
"""
import json

from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState

from ._ros2 import common_inputs, take
from .ros2_publisher import message_type

SPEC = NodeSpec(
    id="isaacsim.ros2.bridge.ROS2Subscriber",
    version=1,
    aliases=("omni.isaac.ros2_bridge.ROS2Subscriber",),
    description=(
        "On execIn, takes the newest messagePackage/messageSubfolder/messageName message on topicName and "
        "outputs it as a JSON object; execOut fires when a new message was taken."),
    categories=("isaacRos2",),
    ui_name="ROS2 Subscriber",
    inputs=common_inputs("topic", exec_description="Check for a new message") + (
        Attribute("messagePackage", "string", default="std_msgs", description="Package of the message type"),
        Attribute("messageSubfolder", "string", default="msg", description="Subfolder (msg)"),
        Attribute("messageName", "string", default="String", description="Message type name"),
    ),
    outputs=(
        Attribute("execOut", "execution", description="Fires when a new message arrived"),
        Attribute("message", "string", default="", description="The message as a JSON object"),
    ),
)


def compute(db):
    if db.inputs.execIn != ExecState.ENABLED:
        return
    from graphflow.ros2.messages import MessageError, complete, type_name

    try:
        full_type = type_name(message_type(db))
    except MessageError as error:
        db.error(str(error))
    message = take(db, full_type)
    if message is None:
        if not db.outputs.message:   # nothing received yet: the type's defaults, as Kit's field outputs
            db.outputs.message = json.dumps(complete(full_type, {}), sort_keys=True)
        return
    db.outputs.message = json.dumps(message, sort_keys=True)
    db.outputs.execOut = ExecState.ENABLED
