"""omni.graph.nodes.ArrayRotate: an array shifted by some steps, wrapping around."""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._math import plain

SPEC = NodeSpec(
    id="omni.graph.nodes.ArrayRotate",
    version=1,
    description=(
        "outputs:array = array shifted steps places to the right, the last elements wrapping to the front; "
        "a negative steps shifts left."),
    categories=("math:array",),
    ui_name="Rotate Array",
    inputs=(
        Attribute("array", "any", default=(), description="The array"),
        Attribute("steps", "int", default=0, description="Places to shift right (negative: left)"),
    ),
    outputs=(
        Attribute("array", "any", description="The shifted array"),
    ),
)


def compute(db):
    array = plain(db.inputs.array)
    if not isinstance(array, tuple):
        db.error(f"inputs:array must be an array, got {array!r}")
    if not array:
        db.outputs.array = array
        return
    shift = db.inputs.steps % len(array)
    db.outputs.array = array[-shift:] + array[:-shift] if shift else array
