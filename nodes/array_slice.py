"""omni.graph.nodes.ArraySlice: the elements of an array between two indices."""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._math import plain

SPEC = NodeSpec(
    id="omni.graph.nodes.ArraySlice",
    version=1,
    description=(
        "outputs:array = array[start:end] (end excluded; useLength: to the end). Negative indices count from "
        "the end; indices are clamped to 0..length; start >= end gives an empty array. A string slices by "
        "characters."),
    categories=("math:array",),
    ui_name="Get Array Slice",
    inputs=(
        Attribute("array", "any", default=(), description="The array (or string)"),
        Attribute("end", "int", default=0, description="The end index, excluded"),
        Attribute("start", "int", default=0, description="The start index"),
        Attribute("useLength", "bool", default=True, description="Slice to the end of the array, ignoring end"),
    ),
    outputs=(
        Attribute("array", "any", description="The slice"),
    ),
)


def _clamped(index: int, length: int) -> int:
    return min(max(index + length if index < 0 else index, 0), length)


def compute(db):
    array = plain(db.inputs.array)
    if not isinstance(array, (tuple, str)):
        db.error(f"inputs:array must be an array or string, got {array!r}")
    start = _clamped(db.inputs.start, len(array))
    end = len(array) if db.inputs.useLength else _clamped(db.inputs.end, len(array))
    db.outputs.array = array[start:end] if start < end else array[:0]
