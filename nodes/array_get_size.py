"""omni.graph.nodes.ArrayGetSize: how many elements an array has."""
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.ArrayGetSize",
    version=1,
    description="outputs:size = the number of elements of the array.",
    categories=("math:array",),
    ui_name="Array Get Size",
    inputs=(
        Attribute("array", "any", description="The array"),
    ),
    outputs=(
        Attribute("size", "int", description="Number of elements"),
    ),
)


def compute(db):
    array = db.inputs.array
    if array is None:
        array = ()
    if not isinstance(array, tuple):
        db.error(f"inputs:array is not an array: {array!r}")
    db.outputs.size = len(array)
