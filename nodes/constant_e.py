"""omni.graph.nodes.ConstantE: a multiple of Euler's number e."""
import math

from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.ConstantE",
    version=1,
    description="outputs:value = factor * e (2.71828...).",
    categories=("constants",),
    inputs=(
        Attribute("factor", "double", default=1.0, description="Multiply e by this"),
    ),
    outputs=(
        Attribute("value", "double", description="factor * e"),
    ),
)


def compute(db):
    db.outputs.value = db.inputs.factor * math.e
