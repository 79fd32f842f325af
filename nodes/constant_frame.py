"""omni.graph.nodes.ConstantFrame: a 4x4 coordinate frame constant."""
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.ConstantFrame",
    version=1,
    description=(
        "Holds a 4x4 coordinate frame constant (Kit's frame[4]: 16 values row by row; identity by default) set on inputs:value and outputs it on outputs:value. "
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
