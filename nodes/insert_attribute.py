"""omni.graph.nodes.InsertAttribute: a bundle plus one attribute taken from the node's own input."""
from graphflow.bundles import BundleAttribute, type_of_value
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.InsertAttribute",
    version=1,
    description=(
        "outputs:data = the bundle 'data' with attrToInsert added as the attribute outputAttrName (replacing "
        "one of that name). Its type is read from the value: bool, int64, double, token, their tuples "
        "(double[3], int[2], ...) and arrays."),
    categories=("bundle",),
    ui_name="Insert Attribute",
    inputs=(
        Attribute("attrToInsert", "any", description="The value to insert"),
        Attribute("data", "bundle", description="The bundle to insert it into"),
        Attribute("outputAttrName", "token", default="attr0", description="The name of the inserted attribute"),
    ),
    outputs=(
        Attribute("data", "bundle", description="The bundle with the attribute inserted"),
    ),
)


def compute(db):
    value, name = db.inputs.attrToInsert, db.inputs.outputAttrName
    if not name:
        db.error("no attribute name: inputs:outputAttrName is empty")
    type_name = type_of_value(value)
    if type_name is None:
        db.error(f"cannot insert {value!r} as '{name}': no attribute type holds it (connect attrToInsert)")
    db.outputs.data = db.inputs.data.with_attribute(BundleAttribute(name, type_name, value))
