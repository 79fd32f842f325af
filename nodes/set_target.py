"""omni.graph.nodes.SetTarget: a target array with the target at an index replaced."""
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.SetTarget",
    version=1,
    description=(
        "outputs:targets = targets with the one at index (in [-length, length); negative counts from the end) "
        "replaced by setTarget. An index out of range is an error."),
    categories=("sceneGraph",),
    ui_name="Set Target",
    inputs=(
        Attribute("index", "int", default=0, description="Which target, in [-length, length)"),
        Attribute("setTarget", "target", description="The target to put there"),
        Attribute("targets", "target", description="The input target array"),
    ),
    outputs=(
        Attribute("targets", "target", description="The modified target array"),
    ),
)


def compute(db):
    targets, new = list(db.inputs.targets or ()), tuple(db.inputs.setTarget or ())
    if len(new) != 1:
        db.error(f"inputs:setTarget must hold one prim, got {len(new)}")
    if not -len(targets) <= db.inputs.index < len(targets):
        db.error(f"inputs:index {db.inputs.index} is out of range for {len(targets)} targets")
    targets[db.inputs.index] = new[0]
    db.outputs.targets = tuple(targets)
