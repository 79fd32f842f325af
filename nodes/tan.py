"""omni.graph.nodes.Tan: tangent of an angle in degrees."""
import math

from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._math import compute_unary

SPEC = NodeSpec(
    id="omni.graph.nodes.Tan",
    version=1,
    description="outputs:value = tan(value), value in degrees; tuples and arrays elementwise.",
    categories=("math:operator",),
    ui_name="Tan",
    inputs=(
        Attribute("value", "any", description="Angle, degrees"),
    ),
    outputs=(
        Attribute("value", "any", description="Its tangent"),
    ),
)


def compute(db):
    compute_unary(db, lambda degrees: math.tan(math.radians(degrees)), "value", "value")
