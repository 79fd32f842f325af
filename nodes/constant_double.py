"""omni.graph.nodes.ConstantDouble: a double constant."""
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.ConstantDouble",
    version=1,
    description=(
        "Holds a double constant set on inputs:value and outputs it on outputs:value. "
        "(In OmniGraph files the constant is read from inputs:value itself.)"),
    categories=("constants",),
    inputs=(
        Attribute("value", "double", default=0.0, description="The constant value"),
    ),
    outputs=(
        Attribute("value", "double", description="The constant value"),
    ),
)


def compute(db):
    db.outputs.value = db.inputs.value
