"""omni.graph.nodes.ArrayReplaceValue: the first (or every) occurrence of a value in an array replaced."""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._math import plain

SPEC = NodeSpec(
    id="omni.graph.nodes.ArrayReplaceValue",
    version=1,
    description=(
        "outputs:array = array with the first element equal to value (every one with replaceAll) replaced by "
        "newValue; numbers compare by value (1 equals 1.0)."),
    categories=("math:array",),
    ui_name="Replace Array Value",
    inputs=(
        Attribute("array", "any", default=(), description="The array"),
        Attribute("newValue", "any", description="What to put in its place"),
        Attribute("replaceAll", "bool", default=False, description="Replace every occurrence"),
        Attribute("value", "any", description="The value to replace"),
    ),
    outputs=(
        Attribute("array", "any", description="The array with the value replaced"),
    ),
)


def compute(db):
    array, old, new = plain(db.inputs.array), plain(db.inputs.value), plain(db.inputs.newValue)
    if not isinstance(array, tuple):
        db.error(f"inputs:array must be an array, got {array!r}")
    if old is None or new is None:
        db.error("inputs:value and inputs:newValue need values; connect them or set values")
    result, replacing = [], True
    for item in array:
        if replacing and item == old:
            result.append(new)
            replacing = db.inputs.replaceAll
        else:
            result.append(item)
    db.outputs.array = tuple(result)
