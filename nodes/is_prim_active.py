"""omni.graph.nodes.IsPrimActive: whether a prim is active on the stage."""
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.IsPrimActive",
    version=1,
    description="outputs:active = the prim (primTarget, else the path in prim) is active on the stage.",
    categories=("sceneGraph",),
    ui_name="Is Prim Active",
    inputs=(
        Attribute("prim", "path", default="", description="The prim's path (used when primTarget is unset)"),
        Attribute("primTarget", "target", description="The prim"),
    ),
    outputs=(
        Attribute("active", "bool", description="The prim is active"),
    ),
)


def compute(db):
    path = db.inputs.primTarget[0] if db.inputs.primTarget else db.inputs.prim
    if not path:
        db.error("no prim: set inputs:primTarget or inputs:prim")
    stage = db.world.stage
    if stage is None:
        db.error("this graph names no stage, so there is no prim to query")
    prim = stage.GetPrimAtPath(path)
    if not prim:
        db.error(f"no prim {path} on the stage")
    db.outputs.active = bool(prim.IsActive())
