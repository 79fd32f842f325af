"""omni.graph.action.OnStageEvent: fire when a stage event of the chosen kind happens.

A headless graphflow run has no editor: nothing is saved or selected and the
hierarchy does not change. Its playback starts when the run starts, so the
start-play events (OmniGraph, Simulation, Animation Start Play) fire once, on
the first tick after a reset; the other events never happen in a run (stop-play
would come after the last tick).
"""
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState

EVENTS = ("Saved", "Selection Changed", "Hierarchy Changed", "OmniGraph Start Play", "OmniGraph Stop Play",
          "Simulation Start Play", "Simulation Stop Play", "Animation Start Play", "Animation Stop Play")
START_EVENTS = ("OmniGraph Start Play", "Simulation Start Play", "Animation Start Play")

SPEC = NodeSpec(
    id="omni.graph.action.OnStageEvent",
    version=3,
    compatible_versions=(1, 2),
    description=(
        "Event source. execOut fires when eventName happens: the start-play events fire once on the first "
        "tick of a run; the editor events (saved, selection, hierarchy) and stop-play never happen headless."),
    categories=("graph:action", "event"),
    ui_name="On Stage Event",
    inputs=(
        Attribute("eventName", "token", default="Animation Start Play", allowed_tokens=EVENTS,
                  description="The stage event to wait for"),
        Attribute("onlyPlayback", "bool", default=True,
                  description="Only compute while playing (graphflow always plays while running)"),
    ),
    outputs=(
        Attribute("execOut", "execution", description="Fires when the event happens"),
    ),
    state=(
        Attribute("started", "bool", default=False, description="The start-play event has fired"),
    ),
)


def compute(db):
    if db.inputs.eventName in START_EVENTS and not db.state.started:
        db.state.started = True
        db.outputs.execOut = ExecState.ENABLED
