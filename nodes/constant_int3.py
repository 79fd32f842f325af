"""omni.graph.nodes.ConstantInt3: a int[3] constant."""
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.ConstantInt3",
    version=1,
    description=(
        "Holds a int[3] constant set on inputs:value and outputs it on outputs:value. "
        "(In OmniGraph files the constant is read from inputs:value itself.)"),
    categories=("constants",),
    inputs=(
        Attribute("value", "int[3]", default=(0, 0, 0), description="The constant value"),
    ),
    outputs=(
        Attribute("value", "int[3]", description="The constant value"),
    ),
)


def compute(db):
    db.outputs.value = db.inputs.value
