"""omni.graph.nodes.ConstantTexCoord3f: a texcoordf[3] constant."""
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.ConstantTexCoord3f",
    version=1,
    description=(
        "Holds a texcoordf[3] constant (a UVW texture coordinate) set on inputs:value and outputs it on outputs:value. "
        "(In OmniGraph files the constant is read from inputs:value itself.)"),
    categories=("constants",),
    inputs=(
        Attribute("value", "texcoordf[3]", default=(0.0, 0.0, 0.0), description="The constant value"),
    ),
    outputs=(
        Attribute("value", "texcoordf[3]", description="The constant value"),
    ),
)


def compute(db):
    db.outputs.value = db.inputs.value
