"""omni.graph.nodes.Subtract: a - b, elementwise."""
import operator

from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._math import compute_binary

SPEC = NodeSpec(
    id="omni.graph.nodes.Subtract",
    version=2,
    compatible_versions=(1,),
    description=(
        "outputs:difference = a - b, for numbers, tuples (double[3]) and arrays, "
        "elementwise; a scalar (or a tuple against an array of tuples) is broadcast. "
        "Integers stay integers when both operands are integers."),
    categories=("math:operator",),
    ui_name="Subtract",
    inputs=(
        Attribute("a", "any", description="First operand (number, tuple or array)"),
        Attribute("b", "any", description="Second operand (number, tuple or array)"),
    ),
    outputs=(
        Attribute("difference", "any", description="a - b, elementwise"),
    ),
)


def compute(db):
    compute_binary(db, operator.sub, "difference")
