"""omni.graph.nodes.ReplaceString: the first (or every) occurrence of a substring replaced."""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._math import plain

SPEC = NodeSpec(
    id="omni.graph.nodes.ReplaceString",
    version=1,
    description=(
        "outputs:string = string with the first occurrence of replace (every one with replaceAll) replaced by "
        "value (empty value: removed); an empty replace changes nothing."),
    categories=("function",),
    ui_name="Replace String",
    inputs=(
        Attribute("replace", "any", default="", description="The substring to replace"),
        Attribute("replaceAll", "bool", default=False, description="Replace every occurrence"),
        Attribute("string", "any", default="", description="The base string or token"),
        Attribute("value", "any", default="", description="What to put in its place"),
    ),
    outputs=(
        Attribute("string", "any", description="The output string"),
    ),
)


def compute(db):
    text, old, new = plain(db.inputs.string), plain(db.inputs.replace), plain(db.inputs.value)
    if not all(isinstance(s, str) for s in (text, old, new)):
        db.error(f"inputs:string, replace and value must be strings or tokens, got {text!r}, {old!r}, {new!r}")
    db.outputs.string = text if not old else text.replace(old, new, -1 if db.inputs.replaceAll else 1)
