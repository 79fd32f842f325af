"""omni.graph.nodes.Cos: cosine of an angle in degrees."""
import math

from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._math import compute_unary

SPEC = NodeSpec(
    id="omni.graph.nodes.Cos",
    version=1,
    description="outputs:value = cos(value), value in degrees; tuples and arrays elementwise.",
    categories=("math:operator",),
    ui_name="Cosine",
    inputs=(
        Attribute("value", "any", description="Angle, degrees"),
    ),
    outputs=(
        Attribute("value", "any", description="Its cosine"),
    ),
)


def compute(db):
    compute_unary(db, lambda degrees: math.cos(math.radians(degrees)), "value", "value")
