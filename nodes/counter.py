"""omni.graph.action.Counter: count execution pulses."""
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState

SPEC = NodeSpec(
    id="omni.graph.action.Counter",
    version=1,
    description=(
        "Each execIn pulse adds one to the count and fires execOut. A reset pulse "
        "sets the count back to 0 without firing execOut (a reset and an execIn in "
        "the same compute: reset first, then count 1)."),
    categories=("graph:action", "flowControl"),
    ui_name="Counter",
    inputs=(
        Attribute("execIn", "execution", description="Counts one and fires execOut"),
        Attribute("reset", "execution", description="Sets the count to 0"),
    ),
    outputs=(
        Attribute("count", "int", description="Pulses received since the last reset"),
        Attribute("execOut", "execution", description="Fires after each execIn"),
    ),
    state=(
        Attribute("count", "int", default=0, description="Pulses received since the last reset"),
    ),
)


def compute(db):
    if db.inputs.reset == ExecState.ENABLED:
        db.state.count = 0
    if db.inputs.execIn == ExecState.ENABLED:
        db.state.count += 1
        db.outputs.execOut = ExecState.ENABLED
    db.outputs.count = db.state.count
