"""omni.graph.nodes.GetVariantSetNames: the variant sets of a prim."""
from graphflow.spec import Attribute, NodeSpec

from ._stage_edits import PRIM, PRIM_PATH, USE_PATH, VARIANT_CATEGORIES, on_world, target_prim

SPEC = NodeSpec(
    id="omni.graph.nodes.GetVariantSetNames",
    version=2,
    description="outputs:variantSetNames = the names of the prim's variant sets, as composed now.",
    categories=VARIANT_CATEGORIES,
    ui_name="Get Variant Set Names",
    inputs=(PRIM, USE_PATH, PRIM_PATH),
    outputs=(
        Attribute("variantSetNames", "token[]", description="List of variantSet names"),
    ),
)


def compute(db):
    db.outputs.variantSetNames = on_world(db, db.world.variant_sets, target_prim(db))
