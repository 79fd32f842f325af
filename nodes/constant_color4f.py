"""omni.graph.nodes.ConstantColor4f: a colorf[4] constant."""
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.ConstantColor4f",
    version=1,
    description=(
        "Holds a colorf[4] constant set on inputs:value and outputs it on outputs:value. "
        "(In OmniGraph files the constant is read from inputs:value itself.)"),
    categories=("constants",),
    inputs=(
        Attribute("value", "colorf[4]", default=(0.0, 0.0, 0.0, 0.0), description="The constant value"),
    ),
    outputs=(
        Attribute("value", "colorf[4]", description="The constant value"),
    ),
)


def compute(db):
    db.outputs.value = db.inputs.value
