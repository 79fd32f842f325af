"""omni.graph.nodes.RemoveAttribute: a bundle without the attributes a wildcard list names."""
from graphflow.bundles import PRIM_INTERNAL
from graphflow.spec import Attribute, NodeSpec

from ._bundles import PATTERN_HELP
from .find_prims import wildcard

SPEC = NodeSpec(
    id="omni.graph.nodes.RemoveAttribute",
    version=2,
    compatible_versions=(1,),
    description=(
        "outputs:data = the bundle 'data' without the attributes attrNamesToRemove matches (an empty list "
        "removes nothing); sourcePrimPath and sourcePrimType stay unless allowRemovePrimInternal."),
    categories=("bundle",),
    ui_name="Remove Attributes From Bundles",
    inputs=(
        Attribute("allowRemovePrimInternal", "bool", default=False,
                  description="Let the patterns remove sourcePrimPath and sourcePrimType too"),
        Attribute("attrNamesToRemove", "token", default="", description=f"Attributes to remove: {PATTERN_HELP}"),
        Attribute("data", "bundle", description="The bundle to remove them from"),
    ),
    outputs=(
        Attribute("data", "bundle", description="The bundle without them"),
    ),
)


def compute(db):
    inputs, bundle = db.inputs, db.inputs.data
    patterns = inputs.attrNamesToRemove
    removed = [] if not patterns.split() else [
        attribute.name for attribute in bundle
        if wildcard(patterns, attribute.name) and (inputs.allowRemovePrimInternal or attribute.name not in PRIM_INTERNAL)]
    db.outputs.data = bundle.without(removed)
