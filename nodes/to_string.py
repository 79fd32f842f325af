"""omni.graph.nodes.ToString: any value as text, written the way Kit writes it.

Numbers as C++'s stream would print them (6 significant digits, e.g.
1.23457e+06), arrays and tuples in Python list syntax ([1.5, -0.03]), a token
or string as itself, and an array of tokens with each element in double quotes.
"""
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.ToString",
    version=1,
    description=(
        "outputs:converted = value as a string: numbers with 6 significant digits (C++ stream style), "
        "booleans as true/false, tuples and arrays as [a, b, ...], strings unquoted, strings inside arrays "
        "in double quotes."),
    categories=("function",),
    ui_name="To String",
    inputs=(
        Attribute("value", "any", description="The value to convert"),
    ),
    outputs=(
        Attribute("converted", "string", description="The value as text"),
    ),
)


def compute(db):
    db.outputs.converted = as_text(db.inputs.value, top=True)


def as_text(value, top: bool = False) -> str:
    """Kit's text for *value*; strings are quoted only inside arrays."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float):
        return f"{value:g}"
    if isinstance(value, str):
        return value if top else f'"{value}"'
    if isinstance(value, (tuple, list)):
        return "[" + ", ".join(as_text(item) for item in value) + "]"
    return "" if value is None else str(value)
