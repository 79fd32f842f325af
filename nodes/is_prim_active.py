"""omni.graph.nodes.IsPrimActive: whether a prim is active on the stage."""
from graphflow.spec import Attribute, NodeSpec
from graphflow.world import WorldError

SPEC = NodeSpec(
    id="omni.graph.nodes.IsPrimActive",
    version=1,
    description=(
        "outputs:active = the prim (primTarget, else the path in prim) is active: on the stage as authored "
        "and not switched off since by SetPrimActive."),
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
    try:
        db.outputs.active = db.world.prim_active(path)
    except WorldError as error:
        db.error(str(error))
