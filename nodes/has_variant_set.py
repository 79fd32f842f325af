"""omni.graph.nodes.HasVariantSet: whether a prim has a variant set of a given name."""
from graphflow.spec import Attribute, NodeSpec

from ._stage_edits import PRIM, PRIM_PATH, USE_PATH, VARIANT_CATEGORIES, VARIANT_SET_NAME, on_world, target_prim

SPEC = NodeSpec(
    id="omni.graph.nodes.HasVariantSet",
    version=2,
    description="outputs:exists = the prim has a variant set named variantSetName.",
    categories=VARIANT_CATEGORIES,
    ui_name="Has Variant Set",
    inputs=(PRIM, VARIANT_SET_NAME, USE_PATH, PRIM_PATH),
    outputs=(
        Attribute("exists", "bool", description="Variant exists"),
    ),
)


def compute(db):
    names = on_world(db, db.world.variant_sets, target_prim(db))
    db.outputs.exists = db.inputs.variantSetName in names
