"""omni.graph.nodes.AppendString: value + suffix (Kit's deprecated form of BuildString)."""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._strings import appended

SPEC = NodeSpec(
    id="omni.graph.nodes.AppendString",
    version=1,
    description="outputs:value = value + suffix; a token array has suffix appended to each element.",
    categories=("function",),
    ui_name="Append String (Deprecated)",
    inputs=(
        Attribute("value", "any", default="", description="The string(s) to append to"),
        Attribute("suffix", "any", default="", description="The string to append"),
    ),
    outputs=(
        Attribute("value", "any", description="The new string(s)"),
    ),
)


def compute(db):
    db.outputs.value = appended(db, db.inputs.value, db.inputs.suffix)
