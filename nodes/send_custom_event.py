"""omni.graph.action.SendCustomEvent: send a named event that OnCustomEvent nodes receive next tick."""
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState

from ._app_events import CUSTOM, app_events

SPEC = NodeSpec(
    id="omni.graph.action.SendCustomEvent",
    version=2,
    compatible_versions=(1,),
    description=(
        "On execIn, sends the custom event eventName with path and the bundle 'bundle' as its payload; every "
        "OnCustomEvent listening for that name fires on the next tick (Kit delivers it asynchronously)."),
    categories=("graph:action", "event"),
    ui_name="Send Custom Event",
    inputs=(
        Attribute("bundle", "bundle", description="The payload sent with the event"),
        Attribute("execIn", "execution", description="Send the event"),
        Attribute("eventName", "token", default="", description="The name of the event"),
        Attribute("path", "token", default="", description="The path sent with the event"),
    ),
    outputs=(
        Attribute("execOut", "execution", description="Fires after sending"),
    ),
)


def compute(db):
    if db.inputs.execIn != ExecState.ENABLED:
        return
    if not db.inputs.eventName:
        db.error("inputs:eventName is empty: no event to send")
    app_events(db).send(CUSTOM, db.inputs.eventName, {"!path": db.inputs.path, "!bundle": db.inputs.bundle})
    db.outputs.execOut = ExecState.ENABLED
