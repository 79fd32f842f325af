"""omni.graph.nodes.ConstructArray: build an array from input0..input{arraySize-1}."""
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import TypeMismatch, element_type, parse_type
from graphflow_nodes._math import plain

MAX_INPUTS = 32

# The element types graphflow can represent ("auto" = take the elements as given).
ARRAY_TYPES = (
    "auto", "bool[]", "double[]", "float[]", "half[]", "int[]", "int64[]", "uint[]", "uint64[]",
    "token[]", "string[]",
    "double[2][]", "double[3][]", "double[4][]", "float[2][]", "float[3][]", "float[4][]",
    "half[2][]", "half[3][]", "half[4][]", "int[2][]", "int[3][]", "int[4][]",
    "matrixd[3][]", "matrixd[4][]",
    "colord[3][]", "colorf[3][]", "colord[4][]", "colorf[4][]",
    "normald[3][]", "normalf[3][]", "pointd[3][]", "pointf[3][]",
    "quatd[4][]", "quatf[4][]", "quath[4][]", "vectord[3][]", "vectorf[3][]",
)

SPEC = NodeSpec(
    id="omni.graph.nodes.ConstructArray",
    version=1,
    description=(
        f"outputs:array = (input0, ..., input<arraySize-1>), arraySize 0..{MAX_INPUTS}. "
        "With arrayType 'auto' the elements are taken as given and every one of them "
        "must be set; with an explicit type (e.g. 'double[]', 'token[]', 'double[3][]') "
        "each element is converted to the element type and unset inputs give its zero; an element Kit "
        "saved as token text while its type was unresolved ('-0.9', '(1, 2, 3)') is read as that type."),
    categories=("math:array",),
    ui_name="Make Array",
    inputs=(
        Attribute("arraySize", "int", default=1, minimum=0, maximum=MAX_INPUTS,
                  description="Number of elements, taken from input0 upwards"),
        Attribute("arrayType", "token", default="auto", allowed_tokens=ARRAY_TYPES,
                  description="Type of the output array, or 'auto'"),
    ) + tuple(
        Attribute(f"input{i}", "any", optional=True, description=f"Element {i}")
        for i in range(MAX_INPUTS)
    ),
    outputs=(
        Attribute("array", "any", description="The constructed array"),
    ),
)


def _from_text(text: str):
    """A number, bool or tuple Kit wrote as token text ('-0.9', 'true', '(1, 2, 3)'); the text itself if none."""
    words = [w.strip() for w in text.strip().strip("()[]").split(",")]
    try:
        values = [w.lower() == "true" if w.lower() in ("true", "false") else float(w) for w in words]
    except ValueError:
        return text
    return tuple(values) if len(values) > 1 or text.strip().startswith(("(", "[")) else values[0]


def compute(db):
    size = db.inputs.arraySize
    if not 0 <= size <= MAX_INPUTS:
        db.error(f"inputs:arraySize must be between 0 and {MAX_INPUTS}, got {size}")
        return
    array_type = db.inputs.arrayType or "auto"
    element = None
    if array_type != "auto":
        try:
            element = element_type(parse_type(array_type))
        except ValueError:
            db.error(f"inputs:arrayType {array_type!r} is not an array type graphflow knows")
            return
    items = []
    for i in range(size):
        value = plain(getattr(db.inputs, f"input{i}"))
        if element is None:
            if value is None:
                db.error(f"inputs:input{i} has no value; set it, or set inputs:arrayType "
                         "so unset elements default to zero")
                return
            items.append(value)
        elif value is None:
            items.append(element.default_value())
        else:
            try:
                items.append(element.coerce(_from_text(value) if isinstance(value, str) and element.base
                                            not in ("token", "string") else value))
            except TypeMismatch as error:
                db.error(f"inputs:input{i} does not fit arrayType {array_type}: {error}")
                return
    db.outputs.array = tuple(items)
