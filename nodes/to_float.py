"""omni.graph.nodes.ToFloat: numbers (or bools) as 32-bit floats, keeping tuple and array shapes."""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._math import MathError, elementwise, is_boolean, is_number

SPEC = NodeSpec(
    id="omni.graph.nodes.ToFloat",
    version=1,
    description=(
        "outputs:converted = value rounded to 32-bit floats (true -> 1.0, false -> 0.0); tuples and arrays "
        "elementwise, keeping their shape."),
    categories=("math:conversion",),
    ui_name="To Float",
    inputs=(
        Attribute("value", "any", description="bool, number, or a tuple or array of them"),
    ),
    outputs=(
        Attribute("converted", "any", description="The value(s) as 32-bit floats"),
    ),
)


def compute(db):
    import numpy as np  # only when the node runs: loading the node library imports no numpy

    if db.inputs.value is None:
        db.error("inputs:value has no value; connect it or set a value")
    try:
        db.outputs.converted = elementwise(lambda x: float(np.float32(x)), [db.inputs.value], ("value",),
                                           lambda x: is_boolean(x) or is_number(x), "bools or numbers")
    except MathError as error:
        db.error(str(error))
