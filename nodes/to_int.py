"""omni.graph.nodes.ToInt: bools and numbers as 32-bit signed integers, truncated towards zero."""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._integers import compute_integer

SPEC = NodeSpec(
    id="omni.graph.nodes.ToInt",
    version=1,
    description=(
        "outputs:converted = value as 32-bit signed integers: floats truncated towards zero, true -> 1, false -> 0, "
        "values outside the range wrap around (two's complement); tuples and arrays elementwise, keeping their shape."),
    categories=("math:conversion",),
    ui_name="To Int",
    inputs=(
        Attribute("value", "any", description="bool or number, or a tuple or array of them"),
    ),
    outputs=(
        Attribute("converted", "any", description="int in the input's shape"),
    ),
)


def compute(db):
    compute_integer(db, 32, True, tuples=True)
