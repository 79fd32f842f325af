"""omni.graph.nodes.ArrayRemoveValue: an array without the first (or every) element equal to a value."""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._math import plain

SPEC = NodeSpec(
    id="omni.graph.nodes.ArrayRemoveValue",
    version=1,
    description=(
        "outputs:array = array without the first element equal to value (every such element with "
        "removeAll); found says whether anything was removed."),
    categories=("math:array",),
    ui_name="Remove Array Value",
    inputs=(
        Attribute("array", "any", default=(), description="The array"),
        Attribute("value", "any", description="The value to remove"),
        Attribute("removeAll", "bool", default=False, description="Remove every occurrence"),
    ),
    outputs=(
        Attribute("array", "any", description="The array without it"),
        Attribute("found", "bool", description="A value was removed"),
    ),
)


def compute(db):
    array, value = plain(db.inputs.array), plain(db.inputs.value)
    if not isinstance(array, tuple):
        db.error(f"inputs:array must be an array, got {array!r}")
    if db.inputs.removeAll:
        kept = tuple(item for item in array if item != value)
    else:
        kept = array[:array.index(value)] + array[array.index(value) + 1:] if value in array else array
    db.outputs.array, db.outputs.found = kept, len(kept) != len(array)
