"""omni.graph.nodes.ToRad: angles in degrees as radians."""
import math

from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._math import compute_unary

SPEC = NodeSpec(
    id="omni.graph.nodes.ToRad",
    version=1,
    description="outputs:radians = degrees converted to radians; arrays elementwise.",
    categories=("math:conversion",),
    ui_name="To Radians",
    inputs=(
        Attribute("degrees", "any", description="Angle in degrees (a number or an array of numbers)"),
    ),
    outputs=(
        Attribute("radians", "any", description="The angle in radians"),
    ),
)


def compute(db):
    compute_unary(db, math.radians, "degrees", "radians")
