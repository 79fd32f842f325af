"""graphflow.FormatText: format a value into text (for PrintText)."""
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="graphflow.FormatText",
    version=1,
    description=(
        "outputs:text = format with {value} replaced by inputs:value, using Python "
        "str.format syntax: 'count = {value}', 'x = {value:.3f}', 'first = {value[0]}'. "
        "'{}' also means the value. A bad format is a run-time error."),
    categories=("function",),
    ui_name="Format Text",
    inputs=(
        Attribute("format", "string", default="{value}", description="Format string, e.g. 'count = {value}'"),
        Attribute("value", "any", description="The value to insert"),
    ),
    outputs=(
        Attribute("text", "string", description="The formatted text"),
    ),
)


def compute(db):
    try:
        db.outputs.text = db.inputs.format.format(db.inputs.value, value=db.inputs.value)
    except (KeyError, IndexError, ValueError, TypeError, AttributeError) as error:
        db.error(f"inputs:format {db.inputs.format!r} cannot format {db.inputs.value!r}: "
                 f"{type(error).__name__}: {error}")
