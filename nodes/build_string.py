"""omni.graph.nodes.BuildString: a + b for strings and tokens (Kit's Append String)."""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._strings import appended

SPEC = NodeSpec(
    id="omni.graph.nodes.BuildString",
    version=2,
    description="outputs:value = a + b; a token array a has b appended to each element.",
    categories=("function",),
    ui_name="Append String",
    inputs=(
        Attribute("a", "any", default="", description="The string(s) to append to; sets the output type"),
        Attribute("b", "any", default="", description="The string to append"),
    ),
    outputs=(
        Attribute("value", "any", description="The new string(s)"),
    ),
)


def compute(db):
    db.outputs.value = appended(db, db.inputs.a, db.inputs.b)
