"""omni.graph.nodes.Atan: the angle (degrees) whose tangent is the input."""
import math

from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._math import compute_unary

SPEC = NodeSpec(
    id="omni.graph.nodes.Atan",
    version=1,
    description="outputs:value = atan(value) in degrees, in -90..90; tuples and arrays elementwise.",
    categories=("math:operator",),
    ui_name="Arctangent",
    inputs=(
        Attribute("value", "any", description="A tangent"),
    ),
    outputs=(
        Attribute("value", "any", description="The angle, degrees"),
    ),
)


def compute(db):
    compute_unary(db, lambda tangent: math.degrees(math.atan(tangent)), "value", "value")
