"""omni.graph.nodes.ConstantPi: a multiple of pi."""
import math

from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.ConstantPi",
    version=1,
    description="outputs:value = factor * pi.",
    categories=("constants",),
    inputs=(
        Attribute("factor", "double", default=1.0, description="Multiply pi by this"),
    ),
    outputs=(
        Attribute("value", "double", description="factor * pi"),
    ),
)


def compute(db):
    db.outputs.value = db.inputs.factor * math.pi
