"""omni.graph.nodes.BooleanAnd: logical And of a and b, elementwise."""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._math import compute_binary, is_boolean

SPEC = NodeSpec(
    id="omni.graph.nodes.BooleanAnd",
    version=1,
    description=(
        "outputs:result = a and b for bools, or elementwise for bool arrays (a single "
        "bool is broadcast). Unset inputs read false."),
    categories=("math:condition",),
    ui_name="Boolean And",
    inputs=(
        Attribute("a", "any", default=False, description="bool or bool[]"),
        Attribute("b", "any", default=False, description="bool or bool[]"),
    ),
    outputs=(
        Attribute("result", "any", description="bool, or bool[] for arrays"),
    ),
)


def compute(db):
    compute_binary(db, lambda x, y: bool(x) and bool(y), "result", accept=is_boolean, kind="bools")
