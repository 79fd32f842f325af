"""omni.graph.nodes.ConstantTimecode: a timecode constant."""
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.ConstantTimecode",
    version=1,
    description=(
        "Holds a timecode constant (a time in the stage's time codes) set on inputs:value and outputs it on outputs:value. "
        "(In OmniGraph files the constant is read from inputs:value itself.)"),
    categories=("constants",),
    inputs=(
        Attribute("value", "timecode", default=0.0, description="The constant value"),
    ),
    outputs=(
        Attribute("value", "timecode", description="The constant value"),
    ),
)


def compute(db):
    db.outputs.value = db.inputs.value
