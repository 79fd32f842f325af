"""omni.graph.action.SendMessageBusEvent: push a named event with a payload onto the message bus."""
import json

from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState

from ._app_events import MESSAGE_BUS, app_events

SPEC = NodeSpec(
    id="omni.graph.action.SendMessageBusEvent",
    version=1,
    description=(
        "On execIn, pushes the event eventName onto the application message bus; OnMessageBusEvent nodes "
        "of that name fire on the next tick. Kit builds the payload from the node's dynamic inputs; here it "
        "is messageFields, a JSON object (graphflow import gathers the dynamic inputs into it)."),
    categories=("graph:action", "event"),
    ui_name="Send MessageBus Event",
    inputs=(
        Attribute("execIn", "execution", description="Push the event"),
        Attribute("eventName", "token", default="", description="The name of the event"),
        Attribute("messageFields", "string", default="{}", description="The payload, a JSON object"),
    ),
    outputs=(
        Attribute("execOut", "execution", description="Fires after pushing"),
    ),
)


def validate(node_name, values):
    try:
        payload = json.loads(values.get("messageFields", "{}") or "{}")
    except (TypeError, json.JSONDecodeError) as error:
        return [f"inputs:messageFields: not JSON ({getattr(error, 'msg', error)})"]
    return [] if isinstance(payload, dict) else ["inputs:messageFields: expected a JSON object (the payload)"]


def compute(db):
    if db.inputs.execIn != ExecState.ENABLED:
        return
    if not db.inputs.eventName:
        db.error("inputs:eventName is empty: no event to push")
    try:
        payload = json.loads(db.inputs.messageFields or "{}")
    except json.JSONDecodeError as error:
        db.error(f"inputs:messageFields: not JSON ({error.msg})")
    if not isinstance(payload, dict):
        db.error("inputs:messageFields: expected a JSON object (the payload)")
    app_events(db).send(MESSAGE_BUS, db.inputs.eventName, payload)
    db.outputs.execOut = ExecState.ENABLED
