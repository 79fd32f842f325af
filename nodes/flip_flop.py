"""omni.graph.action.FlipFlop: alternate pulses between 'a' and 'b'."""
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState

SPEC = NodeSpec(
    id="omni.graph.action.FlipFlop",
    version=1,
    description=(
        "Alternates: the 1st, 3rd, 5th ... execIn pulse fires 'a', the 2nd, 4th ... "
        "fires 'b'. isA tells which one fired last."),
    categories=("graph:action", "flowControl"),
    ui_name="Flip Flop",
    inputs=(
        Attribute("execIn", "execution", description="Input execution"),
    ),
    outputs=(
        Attribute("a", "execution", description="Fires on odd pulses (the first one included)"),
        Attribute("b", "execution", description="Fires on even pulses"),
        Attribute("isA", "bool", description="True when 'a' fired last"),
    ),
    state=(
        Attribute("nextIsA", "bool", default=True, description="The next pulse goes to 'a'"),
    ),
)


def compute(db):
    if db.inputs.execIn != ExecState.ENABLED:
        return
    if db.state.nextIsA:
        db.outputs.a = ExecState.ENABLED
        db.outputs.isA = True
    else:
        db.outputs.b = ExecState.ENABLED
        db.outputs.isA = False
    db.state.nextIsA = not db.state.nextIsA
