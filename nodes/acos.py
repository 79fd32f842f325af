"""omni.graph.nodes.Acos: the angle (degrees) whose cosine is the input."""
import math

from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._math import compute_unary

SPEC = NodeSpec(
    id="omni.graph.nodes.Acos",
    version=1,
    description="outputs:value = acos(value) in degrees; tuples and arrays elementwise; outside -1..1 is an error.",
    categories=("math:operator",),
    ui_name="Arccosine",
    inputs=(
        Attribute("value", "any", description="A cosine, -1..1"),
    ),
    outputs=(
        Attribute("value", "any", description="The angle, degrees"),
    ),
)


def compute(db):
    compute_unary(db, lambda cosine: math.degrees(math.acos(cosine)), "value", "value")
