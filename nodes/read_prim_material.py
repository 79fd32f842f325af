"""omni.graph.nodes.ReadPrimMaterial: the material bound to a prim."""
from graphflow.spec import Attribute, NodeSpec

from ._stage_edits import on_world, prim_or_path

SPEC = NodeSpec(
    id="omni.graph.nodes.ReadPrimMaterial",
    version=2,
    compatible_versions=(1,),
    description=(
        "outputs:material / materialPrim = the material bound directly to the prim (prim, else primPath) for "
        "all purposes (UsdShade's direct binding, not one inherited from an ancestor or bound for a purpose "
        "such as 'physics'), as composed now; empty when none is bound."),
    categories=("sceneGraph",),
    ui_name="Read Prim Material",
    inputs=(
        Attribute("prim", "target", description="The prim with the material to be read (takes priority over primPath)"),
        Attribute("primPath", "path", default="", description="Path of the prim with the material to be read"),
    ),
    outputs=(
        Attribute("material", "path", description="The material of the input prim"),
        Attribute("materialPrim", "target", description="The prim containing the material of the input prim"),
    ),
)


def compute(db):
    material = on_world(db, db.world.bound_material, prim_or_path(db, "prim", "primPath"))
    db.outputs.material = material
    db.outputs.materialPrim = (material,) if material else ()
