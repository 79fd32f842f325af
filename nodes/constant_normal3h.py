"""omni.graph.nodes.ConstantNormal3h: a normalh[3] constant."""
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.ConstantNormal3h",
    version=1,
    description=(
        "Holds a normalh[3] constant set on inputs:value and outputs it on outputs:value. "
        "(In OmniGraph files the constant is read from inputs:value itself.)"),
    categories=("constants",),
    inputs=(
        Attribute("value", "normalh[3]", default=(0.0, 0.0, 0.0), description="The constant value"),
    ),
    outputs=(
        Attribute("value", "normalh[3]", description="The constant value"),
    ),
)


def compute(db):
    db.outputs.value = db.inputs.value
