"""omni.graph.nodes.GetVariantSelection: which variant of a prim's variant set is selected."""
from graphflow.spec import Attribute, NodeSpec

from ._stage_edits import PRIM, PRIM_PATH, USE_PATH, VARIANT_CATEGORIES, VARIANT_SET_NAME, on_world, target_prim

SPEC = NodeSpec(
    id="omni.graph.nodes.GetVariantSelection",
    version=2,
    description=("outputs:variantName = the variant selected in the prim's variant set variantSetName, as "
                 "composed now (the file's selection, or the one a SetVariantSelection made in this run; "
                 "empty when none)."),
    categories=VARIANT_CATEGORIES,
    ui_name="Get Variant Selection",
    inputs=(PRIM, VARIANT_SET_NAME, USE_PATH, PRIM_PATH),
    outputs=(
        Attribute("variantName", "token", description="The variant name"),
    ),
)


def compute(db):
    db.outputs.variantName = on_world(db, db.world.variant_selection, target_prim(db), db.inputs.variantSetName)
