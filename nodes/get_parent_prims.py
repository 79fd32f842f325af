"""omni.graph.nodes.GetParentPrims: the parent of each prim path (/World/Cube -> /World)."""
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.GetParentPrims",
    version=1,
    description="outputs:parentPrims = the parent path of each path in prims (/World/Cube -> /World).",
    categories=("sceneGraph",),
    ui_name="Get Target Parents",
    inputs=(
        Attribute("prims", "target", description="Prim paths"),
    ),
    outputs=(
        Attribute("parentPrims", "target", description="Their parents' paths"),
    ),
)


def compute(db):
    db.outputs.parentPrims = tuple(path.rsplit("/", 1)[0] or "/" for path in db.inputs.prims or ())
