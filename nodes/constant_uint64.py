"""omni.graph.nodes.ConstantUInt64: a uint64 constant."""
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.ConstantUInt64",
    version=1,
    description=(
        "Holds a uint64 constant set on inputs:value and outputs it on outputs:value. "
        "(In OmniGraph files the constant is read from inputs:value itself.)"),
    categories=("constants",),
    inputs=(
        Attribute("value", "uint64", default=0, description="The constant value"),
    ),
    outputs=(
        Attribute("value", "uint64", description="The constant value"),
    ),
)


def compute(db):
    db.outputs.value = db.inputs.value
