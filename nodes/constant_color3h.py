"""omni.graph.nodes.ConstantColor3h: a colorh[3] constant."""
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.ConstantColor3h",
    version=1,
    description=(
        "Holds a colorh[3] constant (a half-precision RGB colour) set on inputs:value and outputs it on outputs:value. "
        "(In OmniGraph files the constant is read from inputs:value itself.)"),
    categories=("constants",),
    inputs=(
        Attribute("value", "colorh[3]", default=(0.0, 0.0, 0.0), description="The constant value"),
    ),
    outputs=(
        Attribute("value", "colorh[3]", description="The constant value"),
    ),
)


def compute(db):
    db.outputs.value = db.inputs.value
