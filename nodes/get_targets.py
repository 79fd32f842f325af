"""omni.graph.nodes.GetTargets: a run of targets from an array, from an index."""
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.GetTargets",
    version=1,
    description=(
        "outputs:targets = count targets of targets from index (in [-length, length); negative counts from the "
        "end), as many as there are up to the end; count -1: all to the end. An index out of range is an error."),
    categories=("sceneGraph",),
    ui_name="Get Targets",
    inputs=(
        Attribute("count", "int", default=1, description="How many to return; -1: to the end"),
        Attribute("index", "int", default=0, description="Where to start, in [-length, length)"),
        Attribute("targets", "target", description="The input target array"),
    ),
    outputs=(
        Attribute("targets", "target", description="The targets found"),
    ),
)


def compute(db):
    targets, index = tuple(db.inputs.targets or ()), db.inputs.index
    if not -len(targets) <= index < len(targets):
        db.error(f"inputs:index {index} is out of range for {len(targets)} targets")
    start = index % len(targets)
    end = len(targets) if db.inputs.count < 0 else min(len(targets), start + db.inputs.count)
    db.outputs.targets = targets[start:end]
