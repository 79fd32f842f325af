"""omni.graph.nodes.Round: decimals rounded to a number of decimal places."""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._math import compute_unary

SPEC = NodeSpec(
    id="omni.graph.nodes.Round",
    version=1,
    description=(
        "outputs:output = input rounded to decimals places (negative: places left of the point), halves to "
        "even as Python's round; tuples and arrays elementwise."),
    categories=("math:operator",),
    ui_name="Round",
    inputs=(
        Attribute("input", "any", description="Decimal(s) to round"),
        Attribute("decimals", "int", default=0, description="Decimal places to keep"),
    ),
    outputs=(
        Attribute("output", "any", description="The rounded number(s)"),
    ),
)


def compute(db):
    places = db.inputs.decimals
    compute_unary(db, lambda x: float(round(x, places)), "input", "output")
