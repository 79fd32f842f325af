"""omni.graph.nodes.ClearVariantSelection: block a prim's variant selection, or drop the values written from it."""
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState

from ._stage_edits import LAYER_IDENTIFIER, PRIM, VARIANT_CATEGORIES, VARIANT_SET_NAME, on_world, target_prim

SPEC = NodeSpec(
    id="omni.graph.nodes.ClearVariantSelection",
    version=3,
    compatible_versions=(2,),
    description=(
        "When execIn fires: with setVariant, blocks the selection of the prim's variant set variantSetName "
        "in this run's layer (an empty selection: no variant of the set applies until the world resets); "
        "without it (Kit's default), removes the run-time values SetVariantSelection or BlendVariants wrote "
        "for any variant of the set. Refused, naming the prim, when it would change what is simulated."),
    categories=VARIANT_CATEGORIES,
    ui_name="Clear Variant Selection",
    inputs=(
        Attribute("execIn", "execution", description="Input execution"),
        LAYER_IDENTIFIER,
        PRIM,
        Attribute("setVariant", "bool", default=False,
                  description="Clears the variant selection when finished rather than writing to the attribute values"),
        VARIANT_SET_NAME,
    ),
    outputs=(
        Attribute("execOut", "execution", description="Fires after the edit"),
    ),
)


def compute(db):
    prim, variant_set = target_prim(db), db.inputs.variantSetName
    if db.inputs.setVariant:
        on_world(db, db.world.set_variant_selection, prim, variant_set, "")
    else:
        written: list[str] = []
        for variant in on_world(db, db.world.variant_names, prim, variant_set):
            written.extend(path for path in on_world(db, db.world.variant_values, prim, variant_set, variant)
                           if path not in written)
        if written:
            on_world(db, db.world.clear_stage_values, prim, written, "clearing run-time values")
    db.outputs.execOut = ExecState.ENABLED
