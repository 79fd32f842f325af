"""omni.graph.nodes.AppendArray: several arrays joined into one, in input order."""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._math import plain

INPUTS = 8      # input0, input1 as Kit publishes them, and the dynamic input2... a Kit user adds

SPEC = NodeSpec(
    id="omni.graph.nodes.AppendArray",
    version=1,
    description=(
        "outputs:array = the elements of input0, then of input1, and so on, in order. All inputs are arrays "
        f"of one element type (or all strings, joined as text). Up to {INPUTS} inputs (input0 to "
        f"input{INPUTS - 1}); input0 and input1 must be set, unset further inputs are skipped."),
    categories=("math:array",),
    ui_name="Append Array",
    inputs=tuple(
        Attribute(f"input{i}", "any", optional=i > 1, description="An array to append") for i in range(INPUTS)),
    outputs=(
        Attribute("array", "any", description="The joined array"),
    ),
)


def compute(db):
    arrays = []
    for i in range(INPUTS):
        value = plain(getattr(db.inputs, f"input{i}"))
        if value is None:
            if i < 2:
                db.error(f"inputs:input{i} has no value; connect an array or set one")
            continue
        if not isinstance(value, (tuple, str)):
            db.error(f"inputs:input{i} must be an array, got {value!r}")
        arrays.append((i, value))
    first_index, first = arrays[0]
    for index, value in arrays[1:]:
        if isinstance(value, str) != isinstance(first, str) or not _fits(_shape(value), _shape(first)):
            db.error(f"inputs:input{index} holds {_kind(value)} but inputs:input{first_index} holds {_kind(first)}")
    if isinstance(first, str):
        db.outputs.array = "".join(value for _, value in arrays)
    else:
        db.outputs.array = tuple(element for _, value in arrays for element in value)


def _shape(array):
    """What the array's elements are, for the type check: None for an empty array or a string."""
    if isinstance(array, str) or not array:
        return None
    element = array[0]
    if isinstance(element, tuple):
        return ("tuple", len(element))
    if isinstance(element, bool):
        return ("bool", 0)
    return ("number", 0) if isinstance(element, (int, float)) else (type(element).__name__, 0)


def _fits(shape, other) -> bool:
    return shape is None or other is None or shape == other


def _kind(array) -> str:
    if isinstance(array, str):
        return "a string"
    shape = _shape(array)
    if shape is None:
        return "an empty array"
    name, length = shape
    return f"an array of {length}-tuples" if name == "tuple" else f"an array of {name}s"
