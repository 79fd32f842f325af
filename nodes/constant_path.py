"""omni.graph.nodes.ConstantPath: a prim path constant."""
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.ConstantPath",
    version=1,
    description=(
        "Holds a path constant (a prim path such as /World/robot) set on inputs:value and outputs it on "
        "outputs:value. (In OmniGraph files the constant is read from inputs:value itself.)"),
    categories=("constants",),
    inputs=(
        Attribute("value", "path", default="", description="The constant path"),
    ),
    outputs=(
        Attribute("value", "path", description="The constant path"),
    ),
)


def compute(db):
    db.outputs.value = db.inputs.value
