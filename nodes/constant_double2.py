"""omni.graph.nodes.ConstantDouble2: a double[2] constant."""
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.ConstantDouble2",
    version=1,
    description=(
        "Holds a double[2] constant set on inputs:value and outputs it on outputs:value. "
        "(In OmniGraph files the constant is read from inputs:value itself.)"),
    categories=("constants",),
    inputs=(
        Attribute("value", "double[2]", default=(0.0, 0.0), description="The constant value"),
    ),
    outputs=(
        Attribute("value", "double[2]", description="The constant value"),
    ),
)


def compute(db):
    db.outputs.value = db.inputs.value
