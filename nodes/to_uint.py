"""omni.graph.nodes.ToUint: bools and numbers as 32-bit unsigned integers, truncated towards zero."""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._integers import compute_integer

SPEC = NodeSpec(
    id="omni.graph.nodes.ToUint",
    version=1,
    description=(
        "outputs:converted = value as 32-bit unsigned integers: floats truncated towards zero, true -> 1, false -> 0, "
        "negative values become 2^32 minus their magnitude, larger ones wrap; arrays elementwise."),
    categories=("math:conversion",),
    ui_name="To UInt",
    inputs=(
        Attribute("value", "any", description="bool or number, or an array of them"),
    ),
    outputs=(
        Attribute("converted", "any", description="uint in the input's shape"),
    ),
)


def compute(db):
    compute_integer(db, 32, False, tuples=False)
