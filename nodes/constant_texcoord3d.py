"""omni.graph.nodes.ConstantTexCoord3d: a texcoordd[3] constant."""
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.ConstantTexCoord3d",
    version=1,
    description=(
        "Holds a texcoordd[3] constant (a UVW texture coordinate) set on inputs:value and outputs it on outputs:value. "
        "(In OmniGraph files the constant is read from inputs:value itself.)"),
    categories=("constants",),
    inputs=(
        Attribute("value", "texcoordd[3]", default=(0.0, 0.0, 0.0), description="The constant value"),
    ),
    outputs=(
        Attribute("value", "texcoordd[3]", description="The constant value"),
    ),
)


def compute(db):
    db.outputs.value = db.inputs.value
