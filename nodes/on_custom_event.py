"""omni.graph.action.OnCustomEvent: fires when a SendCustomEvent of its name was sent (the tick before)."""
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import EMPTY_BUNDLE, ExecState

from ._app_events import CUSTOM, app_events

SPEC = NodeSpec(
    id="omni.graph.action.OnCustomEvent",
    version=3,
    compatible_versions=(1, 2),
    description=(
        "Fires execOut on a tick after an event named eventName was sent (by a SendCustomEvent node during "
        "the previous tick); path and bundle are the path and payload sent with it. Several such events in one "
        "tick fire once, with the last one's path and payload."),
    categories=("graph:action", "event"),
    ui_name="On Custom Event",
    inputs=(
        Attribute("eventName", "token", default="", description="The name of the event to listen for"),
        Attribute("onlyPlayback", "bool", default=True,
                  description="Only fire while playing (graphflow always plays while running)"),
    ),
    outputs=(
        Attribute("bundle", "bundle", description="The payload sent with the event"),
        Attribute("execOut", "execution", description="Fires when the event was received"),
        Attribute("path", "token", default="", description="The path sent with the event"),
    ),
)


def compute(db):
    received = app_events(db).received(CUSTOM, db.inputs.eventName)
    if received:
        db.outputs.path = received[-1].get("!path", "")
        db.outputs.bundle = received[-1].get("!bundle", EMPTY_BUNDLE)
        db.outputs.execOut = ExecState.ENABLED
