"""omni.graph.nodes.GetGraphTargetId: a number naming the prim the graph runs for, the same in every run."""
import hashlib

from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.GetGraphTargetId",
    version=1,
    description=(
        "outputs:targetId = a uint64 naming the prim the graph runs for (the graph prim, or an instanced graph's "
        "instance prim): the first 8 bytes, big-endian, of the SHA-256 of its path. Kit's id is a handle of "
        "its running stage that changes from session to session; graphflow's is a function of the path, so "
        "it is the same in every run and process (and different prims get different ids). Kit's node has no "
        "input; graphflow's has targetPath, which graphflow import sets for each instance."),
    categories=("sceneGraph",),
    ui_name="Get Graph Target Id",
    inputs=(
        Attribute("targetPath", "token", default="", description="The target prim path (set on import)"),
    ),
    outputs=(
        Attribute("targetId", "uint64", description="The target prim's id"),
    ),
)


def compute(db):
    if not db.inputs.targetPath:
        db.error("inputs:targetPath is empty: graphflow import sets it to the prim the graph runs for")
    digest = hashlib.sha256(db.inputs.targetPath.encode("utf-8")).digest()
    db.outputs.targetId = int.from_bytes(digest[:8], "big")
