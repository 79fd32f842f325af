"""omni.graph.nodes.ConstantBool: a boolean constant."""
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.ConstantBool",
    version=1,
    description=(
        "Holds a boolean constant set on inputs:value and outputs it on outputs:value. "
        "(In OmniGraph files the constant is read from inputs:value itself.)"),
    categories=("constants",),
    inputs=(
        Attribute("value", "bool", default=False, description="The constant value"),
    ),
    outputs=(
        Attribute("value", "bool", description="The constant value"),
    ),
)


def compute(db):
    db.outputs.value = db.inputs.value
