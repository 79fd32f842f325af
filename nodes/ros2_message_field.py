"""graphflow.ROS2MessageField: one field of a generic ROS 2 subscriber's message.

Kit's ROS2Subscriber grows one output per message field (``outputs:data``,
``outputs:header:stamp:sec``); graphflow's subscriber has one JSON output,
``message``. An Isaac script's or file's connection from a field output is
carried over through this node: ``field`` is Kit's port name after
``outputs:``, nested fields joined by ``:`` as Kit joins them.
"""
import json

from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="graphflow.ROS2MessageField",
    version=1,
    description=(
        "outputs:value = the field of the JSON message named by field ('data', 'header:stamp:sec'); arrays "
        "come out as arrays. The message is a generic ROS2Subscriber's outputs:message."),
    categories=("isaacRos2",),
    ui_name="ROS2 Message Field",
    inputs=(
        Attribute("message", "string", default="", description="A message as a JSON object"),
        Attribute("field", "token", default="data", description="The field, nested names joined by ':'"),
    ),
    outputs=(
        Attribute("value", "any", description="The field's value"),
    ),
)


def compute(db):
    if not db.inputs.message:
        db.error("inputs:message is empty: connect a ROS2Subscriber's outputs:message")
    value = json.loads(db.inputs.message)
    for part in str(db.inputs.field).split(":"):
        if not isinstance(value, dict) or part not in value:
            fields = ", ".join(sorted(value)) if isinstance(value, dict) else "none"
            db.error(f"inputs:field {db.inputs.field!r}: the message has no field {part!r} (fields: {fields})")
        value = value[part]
    db.outputs.value = tuple(value) if isinstance(value, list) else value
