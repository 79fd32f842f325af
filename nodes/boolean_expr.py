"""omni.graph.nodes.BooleanExpr: one of six boolean operations on two inputs."""
import operator

from graphflow.spec import Attribute, NodeSpec

OPERATIONS = {
    "AND": operator.and_, "OR": operator.or_, "XOR": operator.xor,
    "NAND": lambda a, b: not (a and b), "NOR": lambda a, b: not (a or b), "XNOR": lambda a, b: a == b,
}

SPEC = NodeSpec(
    id="omni.graph.nodes.BooleanExpr",
    version=1,
    description="outputs:result = a <operator> b, operator one of AND, OR, NAND, NOR, XOR, XNOR.",
    categories=("math:operator",),
    ui_name="Boolean Expression",
    inputs=(
        Attribute("a", "bool", default=False, description="Input A"),
        Attribute("b", "bool", default=False, description="Input B"),
        Attribute("operator", "token", default="AND", allowed_tokens=tuple(OPERATIONS),
                  description="The operation"),
    ),
    outputs=(
        Attribute("result", "bool", description="The result"),
    ),
)


def compute(db):
    db.outputs.result = bool(OPERATIONS[db.inputs.operator](db.inputs.a, db.inputs.b))
