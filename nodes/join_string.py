"""omni.graph.nodes.JoinString: the elements of a string array joined by a delimiter."""
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.JoinString",
    version=1,
    description="outputs:string = the elements joined with delimiter between each two.",
    categories=("function",),
    ui_name="Join String",
    inputs=(
        Attribute("delimiter", "string", default="", description="Put between the elements"),
        Attribute("elements", "token[]", default=(), description="The strings to join"),
    ),
    outputs=(
        Attribute("string", "string", description="The joined string"),
    ),
)


def compute(db):
    db.outputs.string = db.inputs.delimiter.join(db.inputs.elements)
