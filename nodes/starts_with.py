"""omni.graph.nodes.StartsWith: whether a string starts with another."""
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.StartsWith",
    version=1,
    description="outputs:isPrefix = value starts with prefix (an empty prefix: true).",
    categories=("function",),
    ui_name="Starts With",
    inputs=(
        Attribute("prefix", "string", default="", description="The prefix to test"),
        Attribute("value", "string", default="", description="The string to check"),
    ),
    outputs=(
        Attribute("isPrefix", "bool", description="True when value starts with prefix"),
    ),
)


def compute(db):
    db.outputs.isPrefix = db.inputs.value.startswith(db.inputs.prefix)
