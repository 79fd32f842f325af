"""omni.graph.nodes.GraphTarget: the prim path the graph runs for."""
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.GraphTarget",
    version=1,
    description=(
        "outputs:primPath = the prim the graph runs for: the graph prim itself, or for an instanced graph "
        "(prims naming it in their omniGraphs relationship) each instance's prim. graphflow import imports "
        "an instanced graph once per instance and sets targetPath (deprecated in Kit) to that prim."),
    categories=("sceneGraph",),
    ui_name="Get Graph Target",
    inputs=(
        Attribute("targetPath", "token", default="", description="The target prim path (set on import)"),
    ),
    outputs=(
        Attribute("primPath", "token", description="The target prim path"),
    ),
)


def compute(db):
    db.outputs.primPath = db.inputs.targetPath
