"""omni.graph.nodes.ConstantMatrix2d: a 2x2 double matrix constant."""
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.ConstantMatrix2d",
    version=1,
    description=(
        "Holds a 2x2 double matrix constant (4 values row by row; identity by default) set on inputs:value and outputs it on outputs:value. "
        "(In OmniGraph files the constant is read from inputs:value itself.)"),
    categories=("constants",),
    inputs=(
        Attribute("value", "matrixd[4]", default=(1.0, 0.0, 0.0, 1.0), description="The constant value"),
    ),
    outputs=(
        Attribute("value", "matrixd[4]", description="The constant value"),
    ),
)


def compute(db):
    db.outputs.value = db.inputs.value
