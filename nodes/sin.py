"""omni.graph.nodes.Sin: sine of an angle in degrees."""
import math

from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._math import compute_unary

SPEC = NodeSpec(
    id="omni.graph.nodes.Sin",
    version=1,
    description="outputs:value = sin(value), value in degrees; tuples and arrays elementwise.",
    categories=("math:operator",),
    ui_name="Sine",
    inputs=(
        Attribute("value", "any", description="Angle, degrees"),
    ),
    outputs=(
        Attribute("value", "any", description="Its sine"),
    ),
)


def compute(db):
    compute_unary(db, lambda degrees: math.sin(math.radians(degrees)), "value", "value")
