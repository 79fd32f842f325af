"""omni.graph.nodes.GetTargetsSize: how many prims a target input holds."""
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.GetTargetsSize",
    version=1,
    description="outputs:size = the number of prims in targets.",
    categories=("sceneGraph",),
    ui_name="Get Targets Size",
    inputs=(
        Attribute("targets", "target", description="The prims"),
    ),
    outputs=(
        Attribute("size", "int", description="How many"),
    ),
)


def compute(db):
    db.outputs.size = len(db.inputs.targets or ())
