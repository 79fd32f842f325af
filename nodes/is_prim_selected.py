"""omni.graph.nodes.IsPrimSelected: whether the editor has a prim selected; headless nothing ever is."""
from graphflow.spec import Attribute, NodeSpec
from graphflow.world import WorldError

SPEC = NodeSpec(
    id="omni.graph.nodes.IsPrimSelected",
    version=1,
    description=(
        "outputs:isSelected = false, always: Kit answers from the editor's stage selection, and a graphflow run "
        "has no editor, so no prim is ever selected (a documented no-op, so GUI graphs import and run). The prim "
        "(prim, else primPath) must be on the stage: a misspelt path fails the run rather than reading false."),
    categories=("sceneGraph",),
    ui_name="Is Prim Selected",
    inputs=(
        Attribute("prim", "target", optional=True, description="The prim to check"),
        Attribute("primPath", "path", default="", optional=True, description="The prim path to check"),
    ),
    outputs=(
        Attribute("isSelected", "bool", description="Whether the prim is selected: false headless"),
    ),
)


def compute(db):
    path = db.inputs.prim[0] if db.inputs.prim else db.inputs.primPath
    if path:
        try:
            db.world.prim_active(path)
        except WorldError as error:
            db.error(str(error))
    db.outputs.isSelected = False
