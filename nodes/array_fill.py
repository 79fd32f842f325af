"""omni.graph.nodes.ArrayFill: an array of the same length, every element fillValue."""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._math import plain

SPEC = NodeSpec(
    id="omni.graph.nodes.ArrayFill",
    version=1,
    description="outputs:array = a copy of array with every element replaced by fillValue.",
    categories=("math:array",),
    ui_name="Fill Array",
    inputs=(
        Attribute("array", "any", default=(), description="The array to be modified"),
        Attribute("fillValue", "any", description="The value to repeat"),
    ),
    outputs=(
        Attribute("array", "any", description="The filled array"),
    ),
)


def compute(db):
    array, value = plain(db.inputs.array), plain(db.inputs.fillValue)
    if not isinstance(array, tuple):
        db.error(f"inputs:array must be an array, got {array!r}")
    if value is None:
        db.error("inputs:fillValue has no value; connect it or set a value")
    db.outputs.array = (value,) * len(array)
