"""omni.graph.nodes.RenameAttribute: a bundle with some attributes renamed."""
from graphflow.spec import Attribute, NodeSpec

from ._bundles import attribute, names

SPEC = NodeSpec(
    id="omni.graph.nodes.RenameAttribute",
    version=1,
    description=(
        "outputs:data = the bundle 'data' with each attribute of inputAttrNames renamed to the name at the "
        "same place in outputAttrNames (comma- or space-separated lists); the others are copied as they are. "
        "The node fails when the lists differ in length or a listed attribute is not in the bundle."),
    categories=("bundle",),
    ui_name="Rename Attributes In Bundles",
    inputs=(
        Attribute("data", "bundle", description="The bundle whose attributes are renamed"),
        Attribute("inputAttrNames", "token", default="", description="The attributes to rename"),
        Attribute("outputAttrNames", "token", default="", description="Their new names, in the same order"),
    ),
    outputs=(
        Attribute("data", "bundle", description="The bundle with the attributes renamed"),
    ),
)


def compute(db):
    old, new = names(db.inputs.inputAttrNames), names(db.inputs.outputAttrNames)
    if len(old) != len(new):
        db.error(f"inputAttrNames lists {len(old)} names but outputAttrNames {len(new)}")
    for name in old:
        attribute(db, db.inputs.data, name)
    db.outputs.data = db.inputs.data.renamed(dict(zip(old, new)))
