"""graphflow.FormatText: format a value into text (for PrintText)."""
import re
import string

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


MAX_TEXT_LENGTH = 1_000_000   # characters of outputs:text: more is runaway growth, not a message
MAX_FIELD_WIDTH = 1000   # characters: a wider field ('{value:999999999}') is a typo that would print gigabytes


def _oversized_field(format_string: str) -> str | None:
    """The first replacement field whose width or precision is too large (or set from a value), if any."""
    try:
        fields = list(string.Formatter().parse(format_string))
    except ValueError:
        return None   # malformed: str.format reports it
    for _literal, _name, spec, _conversion in fields:
        if spec and ("{" in spec or any(int(number) > MAX_FIELD_WIDTH for number in re.findall(r"\d+", spec))):
            return spec
    return None


def validate(node_name, values):
    spec = _oversized_field(values.get("format", "")) if isinstance(values.get("format"), str) else None
    return [f"inputs:format: field width or precision {spec!r} is more than {MAX_FIELD_WIDTH} characters "
            f"(or set from a value)"] if spec is not None else []


def compute(db):
    spec = _oversized_field(db.inputs.format)
    if spec is not None:
        db.error(f"inputs:format: field width or precision {spec!r} is more than {MAX_FIELD_WIDTH} characters "
                 f"(or set from a value)")
    try:
        text = db.inputs.format.format(db.inputs.value, value=db.inputs.value)
    except (KeyError, IndexError, ValueError, TypeError, AttributeError) as error:
        db.error(f"inputs:format {db.inputs.format!r} cannot format {_shown(db.inputs.value)}: "
                 f"{type(error).__name__}: {error}")
    if len(text) > MAX_TEXT_LENGTH:   # e.g. a variable fed back through '{value}{value}': doubles every tick
        db.error(f"outputs:text would be {len(text)} characters, more than {MAX_TEXT_LENGTH}")
    db.outputs.text = text


def _shown(value) -> str:
    text = repr(value)
    return text if len(text) <= 80 else text[:77] + "..."
