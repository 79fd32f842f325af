"""omni.graph.nodes.Asin: the angle (degrees) whose sine is the input."""
import math

from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._math import compute_unary

SPEC = NodeSpec(
    id="omni.graph.nodes.Asin",
    version=1,
    description="outputs:value = asin(value) in degrees; tuples and arrays elementwise; outside -1..1 is an error.",
    categories=("math:operator",),
    ui_name="Arcsine",
    inputs=(
        Attribute("value", "any", description="A sine, -1..1"),
    ),
    outputs=(
        Attribute("value", "any", description="The angle, degrees"),
    ),
)


def compute(db):
    compute_unary(db, lambda sine: math.degrees(math.asin(sine)), "value", "value")
