"""omni.graph.nodes.ArrayRemoveIndex: an array without one element."""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._math import plain

SPEC = NodeSpec(
    id="omni.graph.nodes.ArrayRemoveIndex",
    version=1,
    description=(
        "outputs:array = array without the element at index; a negative index counts from the end. An index "
        "outside the array is a run-time error."),
    categories=("math:array",),
    ui_name="Array Remove Index",
    inputs=(
        Attribute("array", "any", default=(), description="The array to be modified"),
        Attribute("index", "int", default=0, description="Element index; negative counts from the end"),
    ),
    outputs=(
        Attribute("array", "any", description="The array without that element"),
    ),
)


def compute(db):
    array = plain(db.inputs.array)
    if not isinstance(array, tuple):
        db.error(f"inputs:array must be an array, got {array!r}")
    index = db.inputs.index
    if not -len(array) <= index < len(array):
        db.error(f"inputs:index {index} is out of range for an array of {len(array)} elements")
    index %= len(array)
    db.outputs.array = array[:index] + array[index + 1:]
