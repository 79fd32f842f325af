"""omni.graph.nodes.ConstantUInt: a uint constant."""
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.ConstantUInt",
    version=1,
    description=(
        "Holds a uint constant set on inputs:value and outputs it on outputs:value. "
        "(In OmniGraph files the constant is read from inputs:value itself.)"),
    categories=("constants",),
    inputs=(
        Attribute("value", "uint", default=0, description="The constant value"),
    ),
    outputs=(
        Attribute("value", "uint", description="The constant value"),
    ),
)


def compute(db):
    db.outputs.value = db.inputs.value
