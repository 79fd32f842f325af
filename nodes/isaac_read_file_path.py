"""isaacsim.core.nodes.IsaacReadFilePath: a text file's contents, read once per run.

A relative path is taken from the graph file's folder (the working folder for
a graph built in memory), so a graph and the files it reads move together. The
file is read the first time the node asks for it after the run starts (or is
reset) and kept for the run; its contents are the node's output, so they are in
the trace. Isaac gives the empty string for a missing file with a warning; here
a missing or unreadable file fails the run with one line naming the node and
the path, since a graph that reads a file needs it. An empty path gives the
empty string with a warning, as Isaac.
"""
from pathlib import Path

from graphflow.node_api import NodeDb
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="isaacsim.core.nodes.IsaacReadFilePath",
    version=1,
    aliases=("omni.isaac.core_nodes.IsaacReadFilePath",),
    description=(
        "outputs:fileContents = the text of the file at path (relative paths from the graph file's folder), "
        "read once when the run starts; a missing file fails the run, an empty path gives the empty string."),
    categories=("isaacCore",),
    ui_name="Isaac Read File Path",
    inputs=(
        # Isaac's .ogn types it 'path' (a file path); graphflow's path type is a prim path, so a string here
        Attribute("path", "string", default="", description="The file, absolute or relative to the graph's folder"),
    ),
    outputs=(
        Attribute("fileContents", "string", default="", description="The file's text (UTF-8)"),
    ),
)


def compute(db):
    path = db.inputs.path
    if path not in db.internal:
        db.internal[path] = _read(db, path)
    db.outputs.fileContents = db.internal[path]


def _read(db: NodeDb, path: str) -> str:
    if not path:
        db.log("inputs:path is empty: fileContents is the empty string", "warning")
        return ""
    file = Path(path).expanduser()
    file = file if file.is_absolute() else db.base_dir / file
    try:
        return file.read_text(encoding="utf-8")
    except FileNotFoundError:
        db.error(f"inputs:path: no file {file}")
    except (OSError, UnicodeDecodeError) as error:
        db.error(f"inputs:path: cannot read {file}: {getattr(error, 'strerror', None) or error}")
