"""omni.graph.nodes.ConstantString: a string constant."""
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.ConstantString",
    version=1,
    description=(
        "Holds a string constant set on inputs:value and outputs it on outputs:value. "
        "(In OmniGraph files the constant is read from inputs:value itself.)"),
    categories=("constants",),
    inputs=(
        Attribute("value", "string", default="", description="The constant value"),
    ),
    outputs=(
        Attribute("value", "string", description="The constant value"),
    ),
)


def compute(db):
    db.outputs.value = db.inputs.value
