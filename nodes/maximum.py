"""omni.graph.nodes.Maximum: the larger of a and b, elementwise."""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._math import compute_binary

SPEC = NodeSpec(
    id="omni.graph.nodes.Maximum",
    version=1,
    description=(
        "outputs:maximum = the larger of a and b, for numbers, tuples (double[3]) and arrays, "
        "elementwise; a scalar (or a tuple against an array of tuples) is broadcast. "
        "Integers stay integers when both operands are integers."),
    categories=("math:operator",),
    ui_name="Maximum",
    inputs=(
        Attribute("a", "any", description="First operand (number, tuple or array)"),
        Attribute("b", "any", description="Second operand (number, tuple or array)"),
    ),
    outputs=(
        Attribute("maximum", "any", description="The larger of a and b"),
    ),
)


def compute(db):
    compute_binary(db, max, "maximum")
