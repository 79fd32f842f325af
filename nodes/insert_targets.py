"""omni.graph.nodes.InsertTargets: targets inserted into a target array at an index."""
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.InsertTargets",
    version=1,
    description="outputs:targets = targets with insertTargets inserted before index (clamped to 0..length).",
    categories=("sceneGraph",),
    ui_name="Insert Targets",
    inputs=(
        Attribute("index", "int", default=0, description="Where to insert, clamped to 0..length"),
        Attribute("insertTargets", "target", description="The targets to insert"),
        Attribute("targets", "target", description="The input target array"),
    ),
    outputs=(
        Attribute("targets", "target", description="The modified target array"),
    ),
)


def compute(db):
    targets = tuple(db.inputs.targets or ())
    index = min(max(db.inputs.index, 0), len(targets))
    db.outputs.targets = targets[:index] + tuple(db.inputs.insertTargets or ()) + targets[index:]
