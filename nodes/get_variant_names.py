"""omni.graph.nodes.GetVariantNames: the variants a variant set of a prim offers."""
from graphflow.spec import Attribute, NodeSpec

from ._stage_edits import PRIM, PRIM_PATH, USE_PATH, VARIANT_CATEGORIES, VARIANT_SET_NAME, on_world, target_prim

SPEC = NodeSpec(
    id="omni.graph.nodes.GetVariantNames",
    version=2,
    description="outputs:variantNames = the variants of the prim's variant set variantSetName, as composed now.",
    categories=VARIANT_CATEGORIES,
    ui_name="Get Variant Names",
    inputs=(PRIM, VARIANT_SET_NAME, USE_PATH, PRIM_PATH),
    outputs=(
        Attribute("variantNames", "token[]", description="List of variant names"),
    ),
)


def compute(db):
    db.outputs.variantNames = on_world(db, db.world.variant_names, target_prim(db), db.inputs.variantSetName)
