"""omni.graph.nodes.ToUint64: bools and numbers as 64-bit unsigned integers, truncated towards zero."""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._integers import compute_integer

SPEC = NodeSpec(
    id="omni.graph.nodes.ToUint64",
    version=1,
    description=(
        "outputs:converted = value as 64-bit unsigned integers: floats truncated towards zero, true -> 1, false -> 0, "
        "negative values become 2^64 minus their magnitude, larger ones wrap; arrays elementwise."),
    categories=("math:conversion",),
    ui_name="To UInt64",
    inputs=(
        Attribute("value", "any", description="bool or number, or an array of them"),
    ),
    outputs=(
        Attribute("converted", "any", description="uint64 in the input's shape"),
    ),
)


def compute(db):
    compute_integer(db, 64, False, tuples=False)
