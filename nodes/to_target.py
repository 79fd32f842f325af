"""omni.graph.nodes.ToTarget: prim paths (a string, token or token array) as a target."""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._math import plain

SPEC = NodeSpec(
    id="omni.graph.nodes.ToTarget",
    version=1,
    description=(
        "outputs:converted = the prim path(s) in value as a target: a path string or token gives one prim, a "
        "token array one prim per element, an empty string none. Kit adds an empty path for text that is not "
        "a prim path; graphflow refuses it, naming it."),
    categories=("sceneGraph",),
    ui_name="To Target",
    inputs=(
        Attribute("value", "any", description="A prim path, or an array of them"),
    ),
    outputs=(
        Attribute("converted", "target", description="The prims as a target"),
    ),
)


def compute(db):
    value = plain(db.inputs.value)
    paths = () if value in (None, "") else (value,) if isinstance(value, str) else value
    if not isinstance(paths, tuple) or not all(isinstance(path, str) for path in paths):
        db.error(f"inputs:value must be a prim path or an array of them, got {value!r}")
    bad = [path for path in paths if not path.startswith("/")]
    if bad:
        db.error(f"inputs:value: {', '.join(repr(path) for path in bad)} is not an absolute prim path")
    db.outputs.converted = tuple(paths)
