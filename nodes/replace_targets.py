"""omni.graph.nodes.ReplaceTargets: every occurrence of some targets replaced by others (or removed)."""
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.ReplaceTargets",
    version=1,
    description=(
        "outputs:targets = targets with each occurrence of replaceTargets[i] replaced by setTargets[i] (element "
        "by element); setTargets empty: those targets are removed. The two lists must otherwise be as long."),
    categories=("sceneGraph",),
    ui_name="Replace Targets",
    inputs=(
        Attribute("replaceTargets", "target", description="The targets to replace"),
        Attribute("setTargets", "target", description="The new targets; empty removes them"),
        Attribute("targets", "target", description="The input target array"),
    ),
    outputs=(
        Attribute("targets", "target", description="The modified target array"),
    ),
)


def compute(db):
    old, new = tuple(db.inputs.replaceTargets or ()), tuple(db.inputs.setTargets or ())
    if new and len(new) != len(old):
        db.error(f"inputs:setTargets has {len(new)} paths for {len(old)} in inputs:replaceTargets")
    mapping = dict(zip(old, new))
    db.outputs.targets = tuple(mapping.get(path, path) for path in db.inputs.targets or ()
                               if new or path not in old)
