"""omni.graph.nodes.ConstantNormal3f: a normalf[3] constant."""
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.ConstantNormal3f",
    version=1,
    description=(
        "Holds a normalf[3] constant set on inputs:value and outputs it on outputs:value. "
        "(In OmniGraph files the constant is read from inputs:value itself.)"),
    categories=("constants",),
    inputs=(
        Attribute("value", "normalf[3]", default=(0.0, 0.0, 0.0), description="The constant value"),
    ),
    outputs=(
        Attribute("value", "normalf[3]", description="The constant value"),
    ),
)


def compute(db):
    db.outputs.value = db.inputs.value
