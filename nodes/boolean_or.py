"""omni.graph.nodes.BooleanOr: logical Or of a and b, elementwise."""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._math import compute_binary, is_boolean

SPEC = NodeSpec(
    id="omni.graph.nodes.BooleanOr",
    version=1,
    description=(
        "outputs:result = a or b for bools, or elementwise for bool arrays (a single "
        "bool is broadcast). Unset inputs read false."),
    categories=("math:condition",),
    ui_name="Boolean Or",
    inputs=(
        Attribute("a", "any", default=False, description="bool or bool[]"),
        Attribute("b", "any", default=False, description="bool or bool[]"),
    ),
    outputs=(
        Attribute("result", "any", description="bool, or bool[] for arrays"),
    ),
)


def compute(db):
    compute_binary(db, lambda x, y: bool(x) or bool(y), "result", accept=is_boolean, kind="bools")
