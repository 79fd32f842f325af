"""omni.graph.nodes.ToUchar: bools and numbers as 8-bit unsigned integers, truncated towards zero."""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._integers import compute_integer

SPEC = NodeSpec(
    id="omni.graph.nodes.ToUchar",
    version=1,
    description=(
        "outputs:converted = value as 8-bit unsigned integers: floats truncated towards zero, true -> 1, false -> 0, "
        "negative values become 2^8 minus their magnitude, larger ones wrap; arrays elementwise."),
    categories=("math:conversion",),
    ui_name="To UChar",
    inputs=(
        Attribute("value", "any", description="bool or number, or an array of them"),
    ),
    outputs=(
        Attribute("converted", "any", description="uchar in the input's shape"),
    ),
)


def compute(db):
    compute_integer(db, 8, False, tuples=False)
