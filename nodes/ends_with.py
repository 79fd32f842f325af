"""omni.graph.nodes.EndsWith: whether a string ends with another."""
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.EndsWith",
    version=1,
    description="outputs:isSuffix = value ends with suffix (an empty suffix: true).",
    categories=("function",),
    ui_name="Ends With",
    inputs=(
        Attribute("suffix", "string", default="", description="The suffix to test"),
        Attribute("value", "string", default="", description="The string to check"),
    ),
    outputs=(
        Attribute("isSuffix", "bool", description="True when value ends with suffix"),
    ),
)


def compute(db):
    db.outputs.isSuffix = db.inputs.value.endswith(db.inputs.suffix)
