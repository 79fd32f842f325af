"""omni.graph.nodes.GetString: part of a string, from an index."""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._math import plain

SPEC = NodeSpec(
    id="omni.graph.nodes.GetString",
    version=1,
    description=(
        "outputs:string = count characters of string from index (in [-length, length); negative counts from "
        "the end), as many as there are; count -1: to the end. An index out of range is an error."),
    categories=("function",),
    ui_name="Get String",
    inputs=(
        Attribute("count", "int", default=-1, description="How many characters; -1: to the end"),
        Attribute("index", "int", default=0, description="Where to start, in [-length, length)"),
        Attribute("string", "any", default="", description="The base string or token"),
    ),
    outputs=(
        Attribute("string", "any", description="The extracted string"),
    ),
)


def compute(db):
    text, index = plain(db.inputs.string), db.inputs.index
    if not isinstance(text, str):
        db.error(f"inputs:string must be a string or token, got {text!r}")
    if not -len(text) <= index < len(text):
        db.error(f"inputs:index {index} is out of range for the {len(text)} characters of {text!r}")
    start = index % len(text)
    db.outputs.string = text[start:] if db.inputs.count < 0 else text[start:start + db.inputs.count]
