"""omni.graph.nodes.ConstantInt64: a int64 constant."""
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.ConstantInt64",
    version=1,
    description=(
        "Holds a int64 constant set on inputs:value and outputs it on outputs:value. "
        "(In OmniGraph files the constant is read from inputs:value itself.)"),
    categories=("constants",),
    inputs=(
        Attribute("value", "int64", default=0, description="The constant value"),
    ),
    outputs=(
        Attribute("value", "int64", description="The constant value"),
    ),
)


def compute(db):
    db.outputs.value = db.inputs.value
