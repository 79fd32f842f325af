"""omni.graph.nodes.ArrayIndex: one element of an array."""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._math import plain

SPEC = NodeSpec(
    id="omni.graph.nodes.ArrayIndex",
    version=1,
    description=(
        "outputs:value = array[index]. A negative index counts from the end "
        "(-1 = last element). An index outside the array is a run-time error."),
    categories=("math:array",),
    ui_name="Array Index",
    inputs=(
        Attribute("array", "any", default=(), description="The array (any array type)"),
        Attribute("index", "int", default=0, description="Element index; negative counts from the end"),
    ),
    outputs=(
        Attribute("value", "any", description="The element"),
    ),
)


def compute(db):
    array = plain(db.inputs.array)
    if array is None:
        array = ()
    if not isinstance(array, tuple):
        db.error(f"inputs:array must be an array, got {array!r}")
        return
    index = db.inputs.index
    if not -len(array) <= index < len(array):
        db.error(f"inputs:index {index} is out of range for an array of {len(array)} elements")
        return
    db.outputs.value = array[index]
