"""omni.graph.nodes.CapitalizeString: a string in upper, lower, capitalized or title case."""
from graphflow.spec import Attribute, NodeSpec

OPERATIONS = {"UpperCase": str.upper, "LowerCase": str.lower, "Capitalize": str.capitalize, "Title": str.title}

SPEC = NodeSpec(
    id="omni.graph.nodes.CapitalizeString",
    version=1,
    description=(
        "outputs:string = string formatted by operation: UpperCase, LowerCase, Capitalize (first letter upper, "
        "the rest lower) or Title (each word capitalized), as Python's str methods do."),
    categories=("function",),
    ui_name="Capitalize String",
    inputs=(
        Attribute("operation", "token", default="UpperCase", allowed_tokens=tuple(OPERATIONS),
                  description="The formatting operation"),
        Attribute("string", "string", default="", description="The base string"),
    ),
    outputs=(
        Attribute("string", "string", description="The formatted string"),
    ),
)


def compute(db):
    db.outputs.string = OPERATIONS[db.inputs.operation](db.inputs.string)
