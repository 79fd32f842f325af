"""omni.graph.nodes.ConstantQuath: a quath[4] constant."""
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.ConstantQuath",
    version=1,
    description=(
        "Holds a quath[4] constant set on inputs:value and outputs it on outputs:value. "
        "(In OmniGraph files the constant is read from inputs:value itself.)"),
    categories=("constants",),
    inputs=(
        Attribute("value", "quath[4]", default=(0.0, 0.0, 0.0, 1.0), description="The constant value"),
    ),
    outputs=(
        Attribute("value", "quath[4]", description="The constant value"),
    ),
)


def compute(db):
    db.outputs.value = db.inputs.value
