"""omni.graph.nodes.ConstantDouble3: a double[3] tuple constant."""
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.ConstantDouble3",
    version=1,
    description=(
        "Holds a double[3] tuple constant set on inputs:value and outputs it on outputs:value. "
        "(In OmniGraph files the constant is read from inputs:value itself.)"),
    categories=("constants",),
    inputs=(
        Attribute("value", "double[3]", default=(0.0, 0.0, 0.0), description="The constant value"),
    ),
    outputs=(
        Attribute("value", "double[3]", description="The constant value"),
    ),
)


def compute(db):
    db.outputs.value = db.inputs.value
