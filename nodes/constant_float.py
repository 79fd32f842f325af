"""omni.graph.nodes.ConstantFloat: a float constant."""
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.ConstantFloat",
    version=1,
    description=(
        "Holds a float constant set on inputs:value and outputs it on outputs:value. "
        "(In OmniGraph files the constant is read from inputs:value itself.)"),
    categories=("constants",),
    inputs=(
        Attribute("value", "float", default=0.0, description="The constant value"),
    ),
    outputs=(
        Attribute("value", "float", description="The constant value"),
    ),
)


def compute(db):
    db.outputs.value = db.inputs.value
