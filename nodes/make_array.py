"""omni.graph.nodes.MakeArray: Kit's older array maker, an array of arraySize elements from the inputs a to e."""
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import TypeMismatch, element_type, parse_type
from graphflow_nodes._math import plain
from graphflow_nodes.construct_array import ARRAY_TYPES

ELEMENTS = ("a", "b", "c", "d", "e")

SPEC = NodeSpec(
    id="omni.graph.nodes.MakeArray",
    version=1,
    description=(
        "outputs:array = the first arraySize of (a, b, c, d, e); past five, e is repeated to fill the array "
        "(arraySize 7: a, b, c, d, e, e, e). With arrayType 'auto' the elements are taken as given and each one "
        "used must be set; with an explicit type (e.g. 'double[]', 'token[]') each is converted to the element "
        "type and an unset one is its zero. ConstructArray replaced it in Kit; Isaac 2022-2023 graphs build "
        "joint-name and velocity arrays with it."),
    categories=("math:array",),
    ui_name="Make Array",
    inputs=(
        Attribute("arraySize", "int", default=0, minimum=0, description="Number of elements"),
        Attribute("arrayType", "token", default="auto", allowed_tokens=ARRAY_TYPES,
                  description="Type of the output array, or 'auto'"),
    ) + tuple(Attribute(name, "any", optional=True, description=f"Element {i + 1}") for i, name in enumerate(ELEMENTS)),
    outputs=(
        Attribute("array", "any", description="The array"),
    ),
)


def compute(db):
    size = db.inputs.arraySize
    if size < 0:
        db.error(f"inputs:arraySize must not be negative, got {size}")
    array_type = db.inputs.arrayType or "auto"
    element = None if array_type == "auto" else element_type(parse_type(array_type))
    items = []
    for i in range(size):
        name = ELEMENTS[min(i, len(ELEMENTS) - 1)]
        value = plain(getattr(db.inputs, name))
        if element is None:
            if value is None:
                db.error(f"inputs:{name} has no value; set it, or set inputs:arrayType so unset elements are zero")
            items.append(value)
        elif value is None:
            items.append(element.default_value())
        else:
            try:
                items.append(element.coerce(value))
            except TypeMismatch as error:
                db.error(f"inputs:{name} does not fit arrayType {array_type}: {error}")
    db.outputs.array = tuple(items)
