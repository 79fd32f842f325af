"""omni.graph.nodes.ToToken: any value as a token (the text of ToString)."""
from graphflow.spec import Attribute, NodeSpec

from .to_string import as_text

SPEC = NodeSpec(
    id="omni.graph.nodes.ToToken",
    version=1,
    description="outputs:converted = value as a token, written as ToString writes it.",
    categories=("function",),
    ui_name="To Token",
    inputs=(
        Attribute("value", "any", description="The value to convert"),
    ),
    outputs=(
        Attribute("converted", "token", description="The value as a token"),
    ),
)


def compute(db):
    db.outputs.converted = as_text(db.inputs.value, top=True)
