"""omni.graph.nodes.GetParentPath: the parent of a path token (/World/Cube -> /World)."""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._math import plain

SPEC = NodeSpec(
    id="omni.graph.nodes.GetParentPath",
    version=1,
    description="outputs:parentPath = the parent of path (/World/Cube -> /World); a token array element by element.",
    categories=("sceneGraph",),
    ui_name="Get Parent Path",
    inputs=(
        Attribute("path", "any", default="", description="A path token, or an array of them"),
    ),
    outputs=(
        Attribute("parentPath", "any", description="The parent path(s)"),
    ),
)


def _parent(path: str) -> str:
    return path.rsplit("/", 1)[0] or "/"


def compute(db):
    path = plain(db.inputs.path)
    if isinstance(path, str):
        db.outputs.parentPath = _parent(path)
    elif isinstance(path, tuple) and all(isinstance(p, str) for p in path):
        db.outputs.parentPath = tuple(_parent(p) for p in path)
    else:
        db.error(f"inputs:path must be a path token or an array of them, got {path!r}")
