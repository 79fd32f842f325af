"""omni.graph.nodes.ConstantDouble4: a double[4] constant."""
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.ConstantDouble4",
    version=1,
    description=(
        "Holds a double[4] constant set on inputs:value and outputs it on outputs:value. "
        "(In OmniGraph files the constant is read from inputs:value itself.)"),
    categories=("constants",),
    inputs=(
        Attribute("value", "double[4]", default=(0.0, 0.0, 0.0, 0.0), description="The constant value"),
    ),
    outputs=(
        Attribute("value", "double[4]", description="The constant value"),
    ),
)


def compute(db):
    db.outputs.value = db.inputs.value
