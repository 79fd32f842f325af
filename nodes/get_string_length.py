"""omni.graph.nodes.GetStringLength: the number of characters of a string."""
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.GetStringLength",
    version=1,
    description="outputs:length = the number of characters of string.",
    categories=("function",),
    ui_name="Get String Length",
    inputs=(
        Attribute("string", "string", default="", description="The string"),
    ),
    outputs=(
        Attribute("length", "uint64", description="Its length"),
    ),
)


def compute(db):
    db.outputs.length = len(db.inputs.string)
