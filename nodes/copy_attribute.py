"""omni.graph.nodes.CopyAttribute: one bundle whole plus chosen attributes of another."""
from graphflow.bundles import BundleAttribute
from graphflow.spec import Attribute, NodeSpec

from ._bundles import attribute, names

SPEC = NodeSpec(
    id="omni.graph.nodes.CopyAttribute",
    version=1,
    description=(
        "outputs:data = every attribute of fullData plus the attributes of partialData listed in "
        "inputAttrNames, named as outputAttrNames lists at the same place (their own names when it is empty); "
        "a copied attribute replaces one of fullData with its name. The node fails when the lists differ in "
        "length or a listed attribute is not in partialData."),
    categories=("bundle",),
    ui_name="Copy Attributes From Bundles",
    inputs=(
        Attribute("fullData", "bundle", description="The bundle copied whole"),
        Attribute("inputAttrNames", "token", default="", description="The attributes of partialData to copy"),
        Attribute("outputAttrNames", "token", default="", description="Their names in the output, in the same order"),
        Attribute("partialData", "bundle", description="The bundle the listed attributes come from"),
    ),
    outputs=(
        Attribute("data", "bundle", description="fullData with the copied attributes"),
    ),
)


def compute(db):
    old = names(db.inputs.inputAttrNames)
    new = names(db.inputs.outputAttrNames) or old
    if len(old) != len(new):
        db.error(f"inputAttrNames lists {len(old)} names but outputAttrNames {len(new)}")
    result = db.inputs.fullData
    for source, target in zip(old, new):
        copied = attribute(db, db.inputs.partialData, source)
        result = result.with_attribute(BundleAttribute(target, copied.type, copied.value))
    db.outputs.data = result
