"""omni.graph.action.OnImpulseEvent: fires once when its state is set from outside."""
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState

SPEC = NodeSpec(
    id="omni.graph.action.OnImpulseEvent",
    version=3,
    description=(
        "Fires execOut once on the next tick after state:enableImpulse is set to "
        "true (by the runtime, a test or a UI), then clears enableImpulse."),
    categories=("graph:action", "event"),
    ui_name="On Impulse Event",
    inputs=(
        Attribute("onlyPlayback", "bool", default=True,
                  description="Only fire while playing (graphflow always plays while running)"),
    ),
    outputs=(
        Attribute("execOut", "execution", description="Fires once per impulse"),
    ),
    state=(
        Attribute("enableImpulse", "bool", default=False,
                  description="Set true to fire execOut once; cleared after firing"),
    ),
)


def compute(db):
    if db.state.enableImpulse:
        db.state.enableImpulse = False
        db.outputs.execOut = ExecState.ENABLED
