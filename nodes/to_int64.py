"""omni.graph.nodes.ToInt64: bools and numbers as 64-bit signed integers, truncated towards zero."""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._integers import compute_integer

SPEC = NodeSpec(
    id="omni.graph.nodes.ToInt64",
    version=1,
    description=(
        "outputs:converted = value as 64-bit signed integers: floats truncated towards zero, true -> 1, false -> 0, "
        "values outside the range wrap around (two's complement); arrays elementwise."),
    categories=("math:conversion",),
    ui_name="To Int64",
    inputs=(
        Attribute("value", "any", description="bool or number, or an array of them"),
    ),
    outputs=(
        Attribute("converted", "any", description="int64 in the input's shape"),
    ),
)


def compute(db):
    compute_integer(db, 64, True, tuples=False)
