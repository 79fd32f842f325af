"""omni.graph.nodes.GetPrimsAtPath: prims from a path token or an array of them."""
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.GetPrimsAtPath",
    version=1,
    description="outputs:prims = the prims at path (a token, or a token array), for inputs that take prims.",
    categories=("sceneGraph",),
    ui_name="Get Prims At Path",
    inputs=(
        Attribute("path", "any", description="A path token or an array of them"),
    ),
    outputs=(
        Attribute("prims", "target", description="The prims at those paths"),
    ),
)


def compute(db):
    path = db.inputs.path
    paths = (path,) if isinstance(path, str) else tuple(path or ())
    if not all(isinstance(p, str) and p.startswith("/") for p in paths):
        db.error(f"inputs:path must be absolute prim paths, got {path!r}")
    db.outputs.prims = paths
