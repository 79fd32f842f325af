"""omni.graph.nodes.ArrayLength: the length of an array attribute of a bundle."""
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import parse_type

from ._bundles import attribute

SPEC = NodeSpec(
    id="omni.graph.nodes.ArrayLength",
    version=1,
    description=(
        "outputs:length = the number of elements of the array attribute attrName of the bundle 'data', 1 "
        "when the attribute is not an array. The node fails, naming what the bundle holds, when it has no "
        "such attribute."),
    categories=("math:array",),
    ui_name="Extract Attribute Array Length",
    inputs=(
        Attribute("attrName", "token", default="points", description="The attribute to measure"),
        Attribute("data", "bundle", description="The bundle holding it"),
    ),
    outputs=(
        Attribute("length", "uint64", description="Its number of elements"),
    ),
)


def compute(db):
    found = attribute(db, db.inputs.data, db.inputs.attrName)
    db.outputs.length = len(found.value) if parse_type(found.type).is_array else 1
