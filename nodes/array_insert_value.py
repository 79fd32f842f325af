"""omni.graph.nodes.ArrayInsertValue: an array with a value inserted at an index (clamped to the ends)."""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._math import plain

SPEC = NodeSpec(
    id="omni.graph.nodes.ArrayInsertValue",
    version=1,
    description=(
        "outputs:array = array with value inserted before index: 0 puts it first, the length last; the index "
        "is clamped to 0..length, so -1 also puts it first and a larger index last."),
    categories=("math:array",),
    ui_name="Insert Array Value",
    inputs=(
        Attribute("array", "any", default=(), description="The array"),
        Attribute("index", "int", default=0, description="Where to insert, clamped to 0..length"),
        Attribute("value", "any", description="The value to insert"),
    ),
    outputs=(
        Attribute("array", "any", description="The array with the value"),
    ),
)


def compute(db):
    array, value = plain(db.inputs.array), plain(db.inputs.value)
    if not isinstance(array, tuple):
        db.error(f"inputs:array must be an array, got {array!r}")
    if value is None:
        db.error("inputs:value has no value; connect it or set a value")
    index = min(max(db.inputs.index, 0), len(array))
    db.outputs.array = array[:index] + (value,) + array[index:]
