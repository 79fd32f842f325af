"""omni.graph.nodes.ArrayAppendValue: an array with a value added at the end."""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._math import plain

SPEC = NodeSpec(
    id="omni.graph.nodes.ArrayAppendValue",
    version=1,
    description="outputs:array = array with value added after its last element.",
    categories=("math:array",),
    ui_name="Append Array Value",
    inputs=(
        Attribute("array", "any", default=(), description="The array"),
        Attribute("value", "any", description="The value to append"),
    ),
    outputs=(
        Attribute("array", "any", description="The array with the value at the end"),
    ),
)


def compute(db):
    array, value = plain(db.inputs.array), plain(db.inputs.value)
    if not isinstance(array, tuple):
        db.error(f"inputs:array must be an array, got {array!r}")
    if value is None:
        db.error("inputs:value has no value; connect it or set a value")
    db.outputs.array = array + (value,)
