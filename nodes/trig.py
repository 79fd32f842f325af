"""omni.graph.nodes.Trig: Kit's older one-node trigonometry (an operation token), in degrees."""
import math

from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._math import compute_unary

OPERATIONS = {
    "SIN": lambda a: math.sin(math.radians(a)), "COS": lambda a: math.cos(math.radians(a)),
    "TAN": lambda a: math.tan(math.radians(a)), "ARCSIN": lambda a: math.degrees(math.asin(a)),
    "ARCCOS": lambda a: math.degrees(math.acos(a)), "DEGREES": math.degrees, "RADIANS": math.radians,
}

SPEC = NodeSpec(
    id="omni.graph.nodes.Trig",
    version=1,
    description=(
        "outputs:result = operation(a): SIN, COS, TAN of an angle in degrees, ARCSIN, ARCCOS in degrees, or "
        "DEGREES / RADIANS conversions."),
    categories=("math:operator", "math:conversion"),
    ui_name="Trigonometric Operation",
    inputs=(
        Attribute("a", "any", description="Input to the function"),
        Attribute("operation", "token", default="SIN", allowed_tokens=tuple(OPERATIONS),
                  description="The operation"),
    ),
    outputs=(
        Attribute("result", "any", description="The result"),
    ),
)


def compute(db):
    compute_unary(db, OPERATIONS[db.inputs.operation], "a", "result")
