"""omni.graph.nodes.ArrayResize: an array cut or padded with zeros to a new size."""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._math import plain

SPEC = NodeSpec(
    id="omni.graph.nodes.ArrayResize",
    version=1,
    description=(
        "outputs:array = array cut to newSize elements, or padded at the end with zeroed elements of the "
        "array's element kind (0, 0.0, false, \"\" or a zero tuple); a negative size gives an empty array. "
        "Padding an empty array needs an element to copy the kind from: a run-time error."),
    categories=("math:array",),
    ui_name="Resize Array",
    inputs=(
        Attribute("array", "any", default=(), description="The array to be modified"),
        Attribute("newSize", "int", default=0, description="The new size; negative counts as 0"),
    ),
    outputs=(
        Attribute("array", "any", description="The resized array"),
    ),
)


def _zero(value):
    if isinstance(value, tuple):
        return tuple(_zero(item) for item in value)
    return type(value)()


def compute(db):
    array = plain(db.inputs.array)
    if not isinstance(array, tuple):
        db.error(f"inputs:array must be an array, got {array!r}")
    size = max(db.inputs.newSize, 0)
    if size <= len(array):
        db.outputs.array = array[:size]
        return
    if not array:
        db.error(f"inputs:array is empty: no element kind to pad it to {size} elements with")
    db.outputs.array = array + (_zero(array[0]),) * (size - len(array))
