"""omni.graph.nodes.AnyZero: which elements of a value are zero, within a tolerance."""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._math import zero_flags

SPEC = NodeSpec(
    id="omni.graph.nodes.AnyZero",
    version=1,
    description=(
        "outputs:result = any of the elements is zero (an element that is itself a tuple or vector is zero when all its numbers are): [3, 0, 1] -> true, [[3, 0, 1], [-5, 4, 17]] -> false; a scalar: whether it is zero. Zero means |x| <= tolerance."),
    categories=("math:condition",),
    ui_name="Any Zero",
    inputs=(
        Attribute("tolerance", "double", default=0.0, description="How close to 0 counts as zero"),
        Attribute("value", "any", description="Value(s) to check"),
    ),
    outputs=(
        Attribute("result", "bool", description="Whether the elements are zero"),
    ),
)


def compute(db):
    db.outputs.result = any(zero_flags(db))
