"""omni.graph.nodes.AppendPath: a relative prim or property path appended to a base path."""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._math import plain

SPEC = NodeSpec(
    id="omni.graph.nodes.AppendPath",
    version=1,
    description=(
        "outputs:path = path with suffix appended as a child (/World + Cube -> /World/Cube, /World + Cube.attr "
        "-> /World/Cube.attr); a token array of paths each get the suffix."),
    categories=("sceneGraph",),
    ui_name="Append Path",
    inputs=(
        Attribute("path", "any", default="", description="Base or prim path token(s) (/World)"),
        Attribute("suffix", "token", default="", description="Relative prim or property path (Cube or Cube.attr)"),
    ),
    outputs=(
        Attribute("path", "any", description="The new path token(s)"),
    ),
)


def _append(db, base: str, suffix: str) -> str:
    if not base.startswith("/") or "." in base.rsplit("/", 1)[-1]:
        db.error(f"inputs:path: {base!r} is not a root or prim path")
    return (base.rstrip("/") + "/" + suffix) if suffix else base


def compute(db):
    path, suffix = plain(db.inputs.path), db.inputs.suffix
    if suffix.startswith("/"):
        db.error(f"inputs:suffix: {suffix!r} is absolute; a relative path is appended")
    if isinstance(path, str):
        db.outputs.path = _append(db, path, suffix)
    elif isinstance(path, tuple) and all(isinstance(p, str) for p in path):
        db.outputs.path = tuple(_append(db, p, suffix) for p in path)
    else:
        db.error(f"inputs:path must be a path token or an array of them, got {path!r}")
