"""omni.graph.nodes.ConstantUChar: a uchar constant."""
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.ConstantUChar",
    version=1,
    description=(
        "Holds a uchar constant (0 to 255) set on inputs:value and outputs it on outputs:value. "
        "(In OmniGraph files the constant is read from inputs:value itself.)"),
    categories=("constants",),
    inputs=(
        Attribute("value", "uchar", default=0, description="The constant value"),
    ),
    outputs=(
        Attribute("value", "uchar", description="The constant value"),
    ),
)


def compute(db):
    db.outputs.value = db.inputs.value
