"""omni.graph.nodes.Divide: a / b, elementwise."""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._math import compute_binary, divide

SPEC = NodeSpec(
    id="omni.graph.nodes.Divide",
    version=1,
    description=(
        "outputs:result = a / b (true division, always floating point), for numbers, "
        "tuples and arrays, elementwise, with a scalar broadcast. Division by zero "
        "is a run-time error naming the node."),
    categories=("math:operator",),
    ui_name="Divide",
    inputs=(
        Attribute("a", "any", description="Dividend (number, tuple or array)"),
        Attribute("b", "any", description="Divisor (number, tuple or array)"),
    ),
    outputs=(
        Attribute("result", "any", description="a / b, elementwise"),
    ),
)


def compute(db):
    compute_binary(db, divide, "result")
