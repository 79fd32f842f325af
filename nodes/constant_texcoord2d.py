"""omni.graph.nodes.ConstantTexCoord2d: a texcoordd[2] constant."""
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.ConstantTexCoord2d",
    version=1,
    description=(
        "Holds a texcoordd[2] constant (a UV texture coordinate) set on inputs:value and outputs it on outputs:value. "
        "(In OmniGraph files the constant is read from inputs:value itself.)"),
    categories=("constants",),
    inputs=(
        Attribute("value", "texcoordd[2]", default=(0.0, 0.0), description="The constant value"),
    ),
    outputs=(
        Attribute("value", "texcoordd[2]", description="The constant value"),
    ),
)


def compute(db):
    db.outputs.value = db.inputs.value
