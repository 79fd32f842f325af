"""omni.graph.nodes.ATan2: the angle (degrees) of the point (b, a), atan2(a, b)."""
import math

from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._math import compute_binary

SPEC = NodeSpec(
    id="omni.graph.nodes.ATan2",
    version=1,
    description="outputs:result = atan2(a, b) in degrees, -180..180; tuples and arrays elementwise.",
    categories=("math:operator",),
    ui_name="Arctangent2",
    inputs=(
        Attribute("a", "any", description="The y of the point"),
        Attribute("b", "any", description="The x of the point"),
    ),
    outputs=(
        Attribute("result", "any", description="atan2(a, b), degrees"),
    ),
)


def compute(db):
    compute_binary(db, lambda a, b: math.degrees(math.atan2(a, b)), "result")
