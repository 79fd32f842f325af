"""omni.graph.nodes.GetGraphTargetPrim: the prim the graph runs for, as a target."""
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.GetGraphTargetPrim",
    version=1,
    description=(
        "outputs:prim = the prim the graph runs for (the graph prim, or an instanced graph's instance prim). "
        "Kit's node has no input; graphflow's has targetPath, which graphflow import sets for each instance."),
    categories=("sceneGraph",),
    ui_name="Get Graph Target Prim",
    inputs=(
        Attribute("targetPath", "token", default="", description="The target prim path (set on import)"),
    ),
    outputs=(
        Attribute("prim", "target", description="The target prim"),
    ),
)


def compute(db):
    if not db.inputs.targetPath:
        db.error("inputs:targetPath is empty: graphflow import sets it to the prim the graph runs for")
    db.outputs.prim = (db.inputs.targetPath,)
