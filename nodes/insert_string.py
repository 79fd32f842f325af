"""omni.graph.nodes.InsertString: a string inserted into another at an index."""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._math import plain

SPEC = NodeSpec(
    id="omni.graph.nodes.InsertString",
    version=1,
    description="outputs:string = string with value inserted before index (clamped to 0..length).",
    categories=("function",),
    ui_name="Insert String",
    inputs=(
        Attribute("index", "int", default=0, description="Where to insert, clamped to 0..length"),
        Attribute("string", "any", default="", description="The base string or token"),
        Attribute("value", "any", default="", description="The string to insert"),
    ),
    outputs=(
        Attribute("string", "any", description="The modified string"),
    ),
)


def compute(db):
    text, value = plain(db.inputs.string), plain(db.inputs.value)
    if not isinstance(text, str) or not isinstance(value, str):
        db.error(f"inputs:string and inputs:value must be strings or tokens, got {text!r} and {value!r}")
    index = min(max(db.inputs.index, 0), len(text))
    db.outputs.string = text[:index] + value + text[index:]
