"""omni.graph.nodes.GetAttributeNames: the names of a bundle's attributes."""
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.GetAttributeNames",
    version=1,
    description=(
        "outputs:output = the names of the attributes of the bundle 'data' (sourcePrimPath and sourcePrimType "
        "included), sorted, or in the bundle's own order when sort is false."),
    categories=("bundle",),
    ui_name="Get Attribute Names From Bundle",
    inputs=(
        Attribute("data", "bundle", description="The bundle to list"),
        Attribute("sort", "bool", default=True, description="Sort the names"),
    ),
    outputs=(
        Attribute("output", "token[]", description="The attribute names"),
    ),
)


def compute(db):
    found = db.inputs.data.names
    db.outputs.output = tuple(sorted(found)) if db.inputs.sort else found
