"""omni.graph.nodes.ConstantColor4d: a colord[4] constant."""
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.ConstantColor4d",
    version=1,
    description=(
        "Holds a colord[4] constant set on inputs:value and outputs it on outputs:value. "
        "(In OmniGraph files the constant is read from inputs:value itself.)"),
    categories=("constants",),
    inputs=(
        Attribute("value", "colord[4]", default=(0.0, 0.0, 0.0, 0.0), description="The constant value"),
    ),
    outputs=(
        Attribute("value", "colord[4]", description="The constant value"),
    ),
)


def compute(db):
    db.outputs.value = db.inputs.value
