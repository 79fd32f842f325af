"""omni.graph.nodes.ConstantTarget: prims held as a target value."""
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.ConstantTarget",
    version=1,
    description=(
        "Holds the prim paths set on inputs:value and outputs them on outputs:value, to share one target "
        "between several nodes. (In OmniGraph files the constant is read from inputs:value itself.)"),
    categories=("constants",),
    inputs=(
        Attribute("value", "target", description="The prims"),
    ),
    outputs=(
        Attribute("value", "target", description="The prims"),
    ),
)


def compute(db):
    db.outputs.value = db.inputs.value
