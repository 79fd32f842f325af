"""omni.graph.nodes.ConstantMatrix4d: a 4x4 double matrix constant."""
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.ConstantMatrix4d",
    version=1,
    description=(
        "Holds a 4x4 double matrix constant (16 values row by row; identity by default) set on inputs:value and outputs it on outputs:value. "
        "(In OmniGraph files the constant is read from inputs:value itself.)"),
    categories=("constants",),
    inputs=(
        Attribute("value", "matrixd[16]", default=(1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0), description="The constant value"),
    ),
    outputs=(
        Attribute("value", "matrixd[16]", description="The constant value"),
    ),
)


def compute(db):
    db.outputs.value = db.inputs.value
