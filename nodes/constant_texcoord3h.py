"""omni.graph.nodes.ConstantTexCoord3h: a texcoordh[3] constant."""
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.ConstantTexCoord3h",
    version=1,
    description=(
        "Holds a texcoordh[3] constant (a UVW texture coordinate) set on inputs:value and outputs it on outputs:value. "
        "(In OmniGraph files the constant is read from inputs:value itself.)"),
    categories=("constants",),
    inputs=(
        Attribute("value", "texcoordh[3]", default=(0.0, 0.0, 0.0), description="The constant value"),
    ),
    outputs=(
        Attribute("value", "texcoordh[3]", description="The constant value"),
    ),
)


def compute(db):
    db.outputs.value = db.inputs.value
