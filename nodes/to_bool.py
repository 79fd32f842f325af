"""omni.graph.nodes.ToBool: numbers as bools (non-zero is true)."""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._math import MathError, elementwise, is_boolean, is_number

SPEC = NodeSpec(
    id="omni.graph.nodes.ToBool",
    version=1,
    description="outputs:converted = value != 0 (a bool stays as it is); arrays elementwise.",
    categories=("math:conversion",),
    ui_name="To Bool",
    inputs=(
        Attribute("value", "any", description="bool or number, or an array of them"),
    ),
    outputs=(
        Attribute("converted", "any", description="bool, or bools in the input's shape"),
    ),
)


def compute(db):
    value = db.inputs.value
    if value is None:
        db.error("inputs:value has no value; connect it or set a value")
    if isinstance(value, tuple) and value and isinstance(value[0], tuple):
        db.error("inputs:value must be a scalar or an array of scalars, got tuples")
    try:
        db.outputs.converted = elementwise(lambda x: x != 0, [value], ("value",),
                                           lambda x: is_boolean(x) or is_number(x), "bools or numbers")
    except MathError as error:
        db.error(str(error))
