"""omni.graph.nodes.ArraySetIndex: a copy of an array with one element replaced."""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._math import plain

SPEC = NodeSpec(
    id="omni.graph.nodes.ArraySetIndex",
    version=1,
    description=(
        "outputs:array = array with the element at index set to value; a negative index counts from the end. "
        "With resizeToFit, an index at or past the end first grows the array to index + 1 elements, the new "
        "ones zero; otherwise an index outside the array is a run-time error."),
    categories=("math:array",),
    ui_name="Set Array Index",
    inputs=(
        Attribute("array", "any", default=(), description="The array to start from"),
        Attribute("index", "int", default=0, description="Element index; negative counts from the end"),
        Attribute("resizeToFit", "bool", default=False, description="Grow the array to reach the index"),
        Attribute("value", "any", description="The new element"),
    ),
    outputs=(
        Attribute("array", "any", description="The modified array"),
    ),
)


def _zero(value):
    if isinstance(value, tuple):
        return tuple(_zero(item) for item in value)
    return type(value)()


def compute(db):
    array, value, index = plain(db.inputs.array), plain(db.inputs.value), db.inputs.index
    if not isinstance(array, tuple):
        db.error(f"inputs:array must be an array, got {array!r}")
    if value is None:
        db.error("inputs:value has no value; connect it or set a value")
    if db.inputs.resizeToFit and index >= len(array):
        array = array + (_zero(value),) * (index + 1 - len(array))
    if not -len(array) <= index < len(array):
        db.error(f"inputs:index {index} is out of range for an array of {len(array)} elements")
    index %= len(array)
    db.outputs.array = array[:index] + (value,) + array[index + 1:]
