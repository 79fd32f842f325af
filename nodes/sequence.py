"""omni.graph.action.Sequence (v1 semantics): pulse a, then b, for every input pulse."""
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState

SPEC = NodeSpec(
    id="omni.graph.action.Sequence",
    version=1,
    description=(
        "For every execIn pulse, fires 'a' and, once everything downstream of 'a' "
        "has finished, fires 'b' (OmniGraph Sequence v1: 'a' is enabled-and-pushed, "
        "the node is re-entered after a's downstream, then 'b' is enabled). "
        "OmniGraph's Sequence v2 alternates instead; use Multisequence for >2 outputs."),
    categories=("graph:action", "flowControl"),
    ui_name="Sequence",
    inputs=(
        Attribute("execIn", "execution", description="Input execution"),
    ),
    outputs=(
        Attribute("a", "execution", description="Fires first"),
        Attribute("b", "execution", description="Fires after everything downstream of 'a' is done"),
    ),
    state=(
        Attribute("pending", "bool", default=False, description="'a' fired; 'b' fires on re-entry"),
    ),
)


def compute(db):
    if db.inputs.execIn == ExecState.ENABLED:
        db.state.pending = True
        db.outputs.a = ExecState.ENABLED_AND_PUSH
    elif db.state.pending:
        db.state.pending = False
        db.outputs.b = ExecState.ENABLED
