"""omni.graph.action.ForEach: run loopBody once per array element within one tick."""
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState

SPEC = NodeSpec(
    id="omni.graph.action.ForEach",
    version=1,
    description=(
        "An execIn pulse runs loopBody once per element of arrayIn, in order, all "
        "within the same tick (enabled-and-pushed, re-entered after the body's "
        "downstream finishes); outputs:element and outputs:arrayIndex hold the "
        "current element and its index. The array is read when execIn fires. "
        "'finished' fires after the last element (at once for an empty array)."),
    categories=("graph:action", "flowControl"),
    ui_name="For Each Loop",
    inputs=(
        Attribute("execIn", "execution", description="Starts the loop"),
        Attribute("arrayIn", "any", default=(), description="The array to loop over (any array type)"),
    ),
    outputs=(
        Attribute("loopBody", "execution", description="Fires once per element"),
        Attribute("element", "any", description="The current element"),
        Attribute("arrayIndex", "int", description="Index of the current element"),
        Attribute("finished", "execution", description="Fires after the last element"),
    ),
    state=(
        Attribute("active", "bool", default=False, description="A loop is running"),
        Attribute("index", "int", default=0, description="Index of the current element"),
    ),
)


def _visit(db, index):
    array = db.internal.get("array", ())
    if index < len(array):
        db.state.active = True
        db.state.index = index
        db.outputs.element = array[index]
        db.outputs.arrayIndex = index
        db.outputs.loopBody = ExecState.ENABLED_AND_PUSH
    else:
        db.state.active = False
        db.internal.pop("array", None)
        db.outputs.finished = ExecState.ENABLED


def compute(db):
    if db.inputs.execIn == ExecState.ENABLED:
        array = db.inputs.arrayIn
        if array is None:
            array = ()
        if hasattr(array, "tolist") and not isinstance(array, str):
            array = array.tolist()
        if not isinstance(array, (tuple, list)):
            db.error(f"inputs:arrayIn must be an array, got {type(array).__name__} {array!r}")
            return
        db.internal["array"] = tuple(array)
        _visit(db, 0)
    elif db.state.active:
        _visit(db, db.state.index + 1)
