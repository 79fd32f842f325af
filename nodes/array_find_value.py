"""omni.graph.nodes.ArrayFindValue: the index of the first element equal to a value, -1 if none."""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._math import plain

SPEC = NodeSpec(
    id="omni.graph.nodes.ArrayFindValue",
    version=1,
    description="outputs:index = the index of the first element of array equal to value, or -1 if there is none.",
    categories=("math:array",),
    ui_name="Find Array Value",
    inputs=(
        Attribute("array", "any", default=(), description="The array to search"),
        Attribute("value", "any", description="The value to find"),
    ),
    outputs=(
        Attribute("index", "int", description="Its first index, -1 if absent"),
    ),
)


def compute(db):
    array, value = plain(db.inputs.array), plain(db.inputs.value)
    if not isinstance(array, tuple):
        db.error(f"inputs:array must be an array, got {array!r}")
    db.outputs.index = array.index(value) if value in array else -1
