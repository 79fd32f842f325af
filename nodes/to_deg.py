"""omni.graph.nodes.ToDeg: angles in radians as degrees."""
import math

from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._math import compute_unary

SPEC = NodeSpec(
    id="omni.graph.nodes.ToDeg",
    version=1,
    description="outputs:degrees = radians converted to degrees; arrays elementwise.",
    categories=("math:conversion",),
    ui_name="To Degrees",
    inputs=(
        Attribute("radians", "any", description="Angle in radians (a number or an array of numbers)"),
    ),
    outputs=(
        Attribute("degrees", "any", description="The angle in degrees"),
    ),
)


def compute(db):
    compute_unary(db, math.degrees, "radians", "degrees")
