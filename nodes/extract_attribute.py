"""omni.graph.nodes.ExtractAttribute: one attribute's value out of a bundle."""
from graphflow.spec import Attribute, NodeSpec

from ._bundles import attribute

SPEC = NodeSpec(
    id="omni.graph.nodes.ExtractAttribute",
    version=1,
    description=(
        "outputs:output = the value of the attribute attrName of the bundle 'data'. The node fails, naming "
        "what the bundle holds, when it has no such attribute."),
    categories=("bundle",),
    ui_name="Extract Attribute",
    inputs=(
        Attribute("attrName", "token", default="points", description="The attribute to extract"),
        Attribute("data", "bundle", description="The bundle to extract it from"),
    ),
    outputs=(
        Attribute("output", "any", description="The attribute's value"),
    ),
)


def compute(db):
    db.outputs.output = attribute(db, db.inputs.data, db.inputs.attrName).value
