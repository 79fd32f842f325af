"""omni.graph.nodes.ConstantQuatf: a quatf[4] constant."""
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.ConstantQuatf",
    version=1,
    description=(
        "Holds a quatf[4] constant set on inputs:value and outputs it on outputs:value. "
        "(In OmniGraph files the constant is read from inputs:value itself.)"),
    categories=("constants",),
    inputs=(
        Attribute("value", "quatf[4]", default=(0.0, 0.0, 0.0, 1.0), description="The constant value"),
    ),
    outputs=(
        Attribute("value", "quatf[4]", description="The constant value"),
    ),
)


def compute(db):
    db.outputs.value = db.inputs.value
