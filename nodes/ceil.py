"""omni.graph.nodes.Ceil: the smallest integer not below a number."""
import math

from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._math import compute_unary

SPEC = NodeSpec(
    id="omni.graph.nodes.Ceil",
    version=1,
    description="outputs:result = the smallest integer not below a, as an integer; tuples and arrays elementwise.",
    categories=("math:operator",),
    ui_name="Ceiling",
    inputs=(
        Attribute("a", "any", description="A decimal number (or tuple or array of them)"),
    ),
    outputs=(
        Attribute("result", "any", description="The integer(s)"),
    ),
)


def compute(db):
    compute_unary(db, math.ceil, "a", "result")
