"""omni.graph.nodes.ConstantColor4h: a colorh[4] constant."""
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.ConstantColor4h",
    version=1,
    description=(
        "Holds a colorh[4] constant (a half-precision RGBA colour) set on inputs:value and outputs it on outputs:value. "
        "(In OmniGraph files the constant is read from inputs:value itself.)"),
    categories=("constants",),
    inputs=(
        Attribute("value", "colorh[4]", default=(0.0, 0.0, 0.0, 0.0), description="The constant value"),
    ),
    outputs=(
        Attribute("value", "colorh[4]", description="The constant value"),
    ),
)


def compute(db):
    db.outputs.value = db.inputs.value
