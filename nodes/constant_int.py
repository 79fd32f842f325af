"""omni.graph.nodes.ConstantInt: an integer constant."""
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.ConstantInt",
    version=1,
    description=(
        "Holds an integer constant set on inputs:value and outputs it on outputs:value. "
        "(In OmniGraph files the constant is read from inputs:value itself.)"),
    categories=("constants",),
    inputs=(
        Attribute("value", "int", default=0, description="The constant value"),
    ),
    outputs=(
        Attribute("value", "int", description="The constant value"),
    ),
)


def compute(db):
    db.outputs.value = db.inputs.value
