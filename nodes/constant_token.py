"""omni.graph.nodes.ConstantToken: a token constant."""
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.ConstantToken",
    version=1,
    description=(
        "Holds a token constant set on inputs:value and outputs it on outputs:value. "
        "(In OmniGraph files the constant is read from inputs:value itself.)"),
    categories=("constants",),
    inputs=(
        Attribute("value", "token", default="", description="The constant value"),
    ),
    outputs=(
        Attribute("value", "token", description="The constant value"),
    ),
)


def compute(db):
    db.outputs.value = db.inputs.value
