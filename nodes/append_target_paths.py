"""omni.graph.nodes.AppendTargetPaths: targets made by appending relative paths to root targets."""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._math import plain

SPEC = NodeSpec(
    id="omni.graph.nodes.AppendTargetPaths",
    version=1,
    description=(
        "outputs:targets = each root target with input0 appended as a child path (/World + Cube -> /World/Cube; "
        "Xform/Cube appends two levels); no root targets: under the stage root. A token array input0 appends "
        "element-wise (root i + input0[i]; one root is used for every element)."),
    categories=("sceneGraph",),
    ui_name="Append Target Paths",
    inputs=(
        Attribute("input0", "any", default="", description="Relative path(s) to append, not starting or ending with /"),
        Attribute("rootTargets", "target", description="The targets to append to; empty: the stage root"),
    ),
    outputs=(
        Attribute("targets", "target", description="The new targets"),
    ),
)


def compute(db):
    relative, roots = plain(db.inputs.input0), tuple(db.inputs.rootTargets or ("",))
    names = (relative,) if isinstance(relative, str) else relative
    if not isinstance(names, tuple) or not all(isinstance(name, str) for name in names):
        db.error(f"inputs:input0 must be a string, token or token array, got {relative!r}")
    for name in names:
        if not name or name.startswith("/") or name.endswith("/"):
            db.error(f"inputs:input0: {name!r} must be a relative path that does not start or end with /")
    if isinstance(relative, str):
        db.outputs.targets = tuple(f"{root.rstrip('/')}/{relative}" for root in roots)
    elif len(roots) in (1, len(names)):
        db.outputs.targets = tuple(f"{roots[i if len(roots) > 1 else 0].rstrip('/')}/{name}"
                                   for i, name in enumerate(names))
    else:
        db.error(f"inputs:rootTargets has {len(roots)} paths and inputs:input0 {len(names)}: element-wise needs "
                 "the same number, or one root")
