"""omni.graph.nodes.WritePrimMaterial: bind a material to a prim."""
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState

from ._stage_edits import LAYER_IDENTIFIER, on_world, prim_or_path

SPEC = NodeSpec(
    id="omni.graph.nodes.WritePrimMaterial",
    version=2,
    compatible_versions=(1,),
    description=(
        "When execIn fires, binds the material (material, else materialPath) directly to the prim (prim, "
        "else primPath) for all purposes, with UsdShade's MaterialBindingAPI, then fires execOut. The binding "
        "lasts until the world resets and never reaches the file. Binding a material with physics properties "
        "to a collider would change its friction, so that fails the run naming the prim; a visual "
        "material binds."),
    categories=("sceneGraph",),
    ui_name="Write Prim Material",
    inputs=(
        Attribute("execIn", "execution", description="Input execution"),
        LAYER_IDENTIFIER,
        Attribute("material", "target", description="The material to be assigned to the prim"),
        Attribute("materialPath", "path", default="", description="The path of the material to be assigned to the prim"),
        Attribute("prim", "target", description="Prim to be assigned a material"),
        Attribute("primPath", "path", default="", description="Path of the prim to be assigned a material"),
    ),
    outputs=(
        Attribute("execOut", "execution", description="Fires after the material was bound"),
    ),
)


def compute(db):
    prim = prim_or_path(db, "prim", "primPath")
    on_world(db, db.world.bind_material, prim, prim_or_path(db, "material", "materialPath"))
    db.outputs.execOut = ExecState.ENABLED
