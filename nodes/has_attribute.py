"""omni.graph.nodes.HasAttribute: whether a bundle holds an attribute of a given name."""
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.HasAttribute",
    version=1,
    description="outputs:output = whether the bundle 'data' holds an attribute named attrName.",
    categories=("bundle",),
    ui_name="Has Attribute",
    inputs=(
        Attribute("attrName", "token", default="points", description="The attribute to look for"),
        Attribute("data", "bundle", description="The bundle to look in"),
    ),
    outputs=(
        Attribute("output", "bool", description="True when the bundle holds the attribute"),
    ),
)


def compute(db):
    db.outputs.output = db.inputs.data.get(db.inputs.attrName) is not None
