"""omni.graph.nodes.Modulo: the remainder of integer a / b (0 when b is 0, as Kit's node)."""
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.Modulo",
    version=1,
    description=(
        "outputs:result = a % b for integers, the remainder of a / b; 0 when b is 0. For negative operands "
        "the sign follows a (C++ %), which Kit leaves undefined."),
    categories=("math:operator",),
    ui_name="Modulo",
    inputs=(
        Attribute("a", "int64", default=0, description="Dividend"),
        Attribute("b", "int64", default=0, description="Divisor"),
    ),
    outputs=(
        Attribute("result", "int64", description="a % b"),
    ),
)


def compute(db):
    a, b = db.inputs.a, db.inputs.b
    if b == 0:
        db.outputs.result = 0
        return
    remainder = abs(a) % abs(b)
    db.outputs.result = -remainder if a < 0 else remainder
