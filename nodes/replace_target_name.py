"""omni.graph.nodes.ReplaceTargetName: targets renamed (their last path element replaced)."""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._math import plain

SPEC = NodeSpec(
    id="omni.graph.nodes.ReplaceTargetName",
    version=1,
    description=(
        "outputs:targets = each target with its last element replaced by newName (/World/Cube + Sphere -> "
        "/World/Sphere); a token array newName renames element-wise."),
    categories=("sceneGraph",),
    ui_name="Replace Target Name",
    inputs=(
        Attribute("newName", "any", default="", description="The new name(s)"),
        Attribute("targets", "target", description="The target array to rename"),
    ),
    outputs=(
        Attribute("targets", "target", description="The renamed targets"),
    ),
)


def compute(db):
    name, targets = plain(db.inputs.newName), tuple(db.inputs.targets or ())
    names = (name,) * len(targets) if isinstance(name, str) else name
    if not isinstance(names, tuple) or not all(isinstance(n, str) and n and "/" not in n for n in names):
        db.error(f"inputs:newName must be a prim name (or an array of them), got {name!r}")
    if len(names) != len(targets):
        db.error(f"inputs:newName has {len(names)} names for {len(targets)} targets")
    db.outputs.targets = tuple(path.rsplit("/", 1)[0] + "/" + new for path, new in zip(targets, names))
