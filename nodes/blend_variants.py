"""omni.graph.nodes.BlendVariants: the values two variants author, blended onto the prim."""
from graphflow.bundles import Bundle, BundleAttribute, type_of_value
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
    id="omni.graph.nodes.BlendVariants",
    version=2,
    compatible_versions=(1,),
    description=(
        "When execIn fires: for every attribute both variantNameA and variantNameB of the variant set author, "
        "writes (1 - blend) a + blend b onto the prim (blend clamped to [0, 1]; floating-point scalars, "
        "vectors, quaternions componentwise and matrices; bool, integer and token values take a below 0.5, "
        "else b), and the material bindings of a below 0.5, else of b. With setVariant and blend 1, selects "
        "variantNameB instead and removes the written values. Writes last until the world resets; a blend "
        "that would change what is simulated fails the run naming the prim. outputs:bundle holds the "
        "blended values, named by their path under the prim."),
    categories=VARIANT_CATEGORIES,
    ui_name="Blend Variants",
    inputs=(
        Attribute("blend", "double", default=0.0, description="The blend value in [0.0, 1.0]"),
        Attribute("execIn", "execution", description="Input execution"),
        LAYER_IDENTIFIER,
        PRIM,
        Attribute("setVariant", "bool", default=False,
                  description="Sets the variant selection when finished rather than writing to the attribute values"),
        Attribute("variantNameA", "token", default="", description="The first variant name"),
        Attribute("variantNameB", "token", default="", description="The second variant name"),
        VARIANT_SET_NAME,
    ),
    outputs=(
        Attribute("bundle", "bundle", description="Output bundle with blended attributes"),
        Attribute("execOut", "execution", description="Fires after the blend"),
    ),
)

DISCRETE = ("bool", "uchar", "token", "int", "uint")
CONTINUOUS = ("half", "float", "double", "timecode", "point", "normal", "vector", "color", "texCoord", "quat",
              "matrix", "frame")


def lerp(a, b, t: float):
    if isinstance(a, tuple):
        return tuple(lerp(x, y, t) for x, y in zip(a, b))
    return (1.0 - t) * a + t * b


def blended(path: str, a, b, t: float, db):
    """One attribute at blend *t*, by its USD type (Kit's rule: continuous types interpolate, the rest switch)."""
    if a.type_name != b.type_name:
        db.error(f"{path}: the variants author different types ({a.type_name}, {b.type_name})")
    if a.type_name.endswith("[]") or not a.type_name.startswith(DISCRETE + CONTINUOUS):
        db.error(f"{path}: a {a.type_name} value cannot be blended")
    if a.type_name.startswith(DISCRETE):
        return a.value if t < 0.5 else b.value
    return lerp(a.value, b.value, t)


def compute(db):
    prim, variant_set = target_prim(db), db.inputs.variantSetName
    name_a, name_b = db.inputs.variantNameA, db.inputs.variantNameB
    t = min(max(float(db.inputs.blend), 0.0), 1.0)
    a = on_world(db, db.world.variant_values, prim, variant_set, name_a)
    b = on_world(db, db.world.variant_values, prim, variant_set, name_b)
    common = [path for path in a if path in b]
    finishing = 1.0 - t < 1e-6 and db.inputs.setVariant
    values = {path: blended(path, a[path], b[path], t, db) for path in common}
    if finishing:
        on_world(db, db.world.set_variant_selection, prim, variant_set, name_b)
        if common:
            on_world(db, db.world.clear_stage_values, prim, common, "clearing run-time values")
    else:
        on_world(db, db.world.write_stage_values, prim, values, f"blending {name_a!r} and {name_b!r} at {t:g}")
    chosen = name_a if t < 0.5 else name_b
    write_bindings(db, on_world(db, db.world.variant_bindings, prim, variant_set, chosen))
    attributes = []
    for path, value in values.items():
        type_name = type_of_value(value)
        if type_name is not None:
            attributes.append(BundleAttribute(path[len(prim):].lstrip("./"), type_name, value))
    db.outputs.bundle = Bundle(tuple(attributes))
    db.outputs.execOut = ExecState.ENABLED
