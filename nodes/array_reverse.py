"""omni.graph.nodes.ArrayReverse: an array in reverse order."""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._math import plain

SPEC = NodeSpec(
    id="omni.graph.nodes.ArrayReverse",
    version=1,
    description="outputs:array = array with its elements in reverse order.",
    categories=("math:array",),
    ui_name="Reverse Array",
    inputs=(
        Attribute("array", "any", default=(), description="The array"),
    ),
    outputs=(
        Attribute("array", "any", description="The reversed array"),
    ),
)


def compute(db):
    array = plain(db.inputs.array)
    if not isinstance(array, (tuple, str)):
        db.error(f"inputs:array must be an array, got {array!r}")
    db.outputs.array = array[::-1]
