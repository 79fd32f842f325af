"""isaacsim.ros2.bridge.ROS2Publisher: any standard ROS 2 message type, fields given as values.

Isaac makes one dynamic input per message field (``inputs:pose:pose:position:x``);
graphflow's node declares ports in one place, so the fields are one JSON
object in ``messageFields`` keyed by Isaac's field paths (``graphflow import``
moves Isaac's field inputs there and says so). Fields not given take the
message's defaults.
"""
import json

from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState

from ._ros2 import common_inputs, publish

SPEC = NodeSpec(
    id="isaacsim.ros2.bridge.ROS2Publisher",
    version=1,
    aliases=("omni.isaac.ros2_bridge.ROS2Publisher",),
    description=(
        "Publishes a messagePackage/messageSubfolder/messageName message (e.g. std_msgs/msg/String) on "
        "topicName, its fields from messageFields: a JSON object keyed by field path "
        "(\"pose:pose:position:x\" or nested objects)."),
    categories=("isaacRos2",),
    ui_name="ROS2 Publisher",
    inputs=common_inputs("topic", exec_description="Publish") + (
        Attribute("messagePackage", "string", default="std_msgs", description="Package of the message type"),
        Attribute("messageSubfolder", "string", default="msg", description="Subfolder (msg)"),
        Attribute("messageName", "string", default="String", description="Message type name"),
        Attribute("messageFields", "string", default="{}", description="JSON object of field values by path"),
    ),
)


def validate(node_name, values):
    text = values.get("messageFields", "{}")
    try:
        fields = json.loads(text)
    except (TypeError, json.JSONDecodeError) as error:
        return [f"inputs:messageFields: not JSON ({getattr(error, 'msg', error)})"]
    return [] if isinstance(fields, dict) else ["inputs:messageFields: expected a JSON object of field values"]


def compute(db):
    if db.inputs.execIn != ExecState.ENABLED:
        return
    from graphflow.ros2.messages import unflatten

    fields = db.internal.get("fields")
    if fields is None or fields[0] != db.inputs.messageFields:
        fields = db.internal["fields"] = (db.inputs.messageFields, unflatten(json.loads(db.inputs.messageFields or "{}")))
    publish(db, message_type(db), fields[1])


def message_type(db) -> str:
    inputs = db.inputs
    return f"{inputs.messagePackage.strip()}/{inputs.messageSubfolder.strip() or 'msg'}/{inputs.messageName.strip()}"
