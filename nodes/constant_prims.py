"""omni.graph.nodes.ConstantPrims: a constant list of prims."""
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.ConstantPrims",
    version=2,
    compatible_versions=(1,),
    description=(
        "Holds the prims set on inputs:value and outputs them on outputs:value. "
        "(In OmniGraph files the constant is read from inputs:value itself.)"),
    categories=("constants", "sceneGraph"),
    ui_name="Constant Prims",
    inputs=(
        Attribute("value", "target", description="The prims"),
    ),
    outputs=(
        Attribute("value", "target", description="The prims"),
    ),
)


def compute(db):
    db.outputs.value = db.inputs.value
