"""omni.graph.nodes.SetVariantSelection: select a variant of a prim, or write its values onto the prim."""
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState

from ._stage_edits import (
    LAYER_IDENTIFIER,
    PRIM,
    VARIANT_CATEGORIES,
    VARIANT_SET_NAME,
    on_world,
    target_prim,
    write_bindings,
)

SPEC = NodeSpec(
    id="omni.graph.nodes.SetVariantSelection",
    version=3,
    compatible_versions=(2,),
    description=(
        "When execIn fires: with setVariant, selects variantName in the prim's variant set variantSetName "
        "(after removing this run's opinions on the attributes that variant authors, so its values show); "
        "without it (Kit's default), writes the values (and material bindings) the variant authors onto the "
        "prims as run-time opinions, leaving the selection as it is. Edits last until the world resets and "
        "never reach the file; one that would change what is simulated (bodies, colliders, joints, masses "
        "or their transforms) fails the run naming the prim."),
    categories=VARIANT_CATEGORIES,
    ui_name="Set Variant Selection",
    inputs=(
        Attribute("execIn", "execution", description="Input execution"),
        LAYER_IDENTIFIER,
        PRIM,
        Attribute("setVariant", "bool", default=False,
                  description="Sets the variant selection when finished rather than writing to the attribute values"),
        Attribute("variantName", "token", default="", description="The variant name"),
        VARIANT_SET_NAME,
    ),
    outputs=(
        Attribute("execOut", "execution", description="Fires after the edit"),
    ),
)


def compute(db):
    prim, variant_set, variant = target_prim(db), db.inputs.variantSetName, db.inputs.variantName
    values = on_world(db, db.world.variant_values, prim, variant_set, variant)
    if db.inputs.setVariant:
        if values:
            on_world(db, db.world.clear_stage_values, prim, list(values), "clearing run-time values")
        on_world(db, db.world.set_variant_selection, prim, variant_set, variant)
    else:
        what = f"writing the values of variant {variant!r}"
        on_world(db, db.world.write_stage_values, prim, values, what)
        write_bindings(db, on_world(db, db.world.variant_bindings, prim, variant_set, variant))
    db.outputs.execOut = ExecState.ENABLED
