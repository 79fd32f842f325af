"""omni.graph.action.OnMessageBusEvent: fires when an event of its name was pushed on the message bus."""
import json

from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState

from ._app_events import MESSAGE_BUS, app_events

SPEC = NodeSpec(
    id="omni.graph.action.OnMessageBusEvent",
    version=2,
    compatible_versions=(1,),
    description=(
        "Fires execOut on a tick after an event named eventName was pushed (by a SendMessageBusEvent node "
        "during the previous tick). Kit copies the payload into matching dynamic outputs; here payload is "
        "the whole payload as a JSON object. Several such events in one tick fire once, with the last one."),
    categories=("graph:action", "event"),
    ui_name="On MessageBus Event",
    inputs=(
        Attribute("eventName", "token", default="", description="The name of the event to listen for"),
        Attribute("onlyPlayback", "bool", default=True,
                  description="Only fire while playing (graphflow always plays while running)"),
    ),
    outputs=(
        Attribute("execOut", "execution", description="Fires when the event was received"),
        Attribute("payload", "string", default="", description="The event's payload, a JSON object"),
    ),
)


def compute(db):
    received = app_events(db).received(MESSAGE_BUS, db.inputs.eventName)
    if received:
        db.outputs.payload = json.dumps(received[-1], sort_keys=True)
        db.outputs.execOut = ExecState.ENABLED
