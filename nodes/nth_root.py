"""omni.graph.nodes.NthRoot: the nth root of a number, elementwise over vectors, matrices and arrays.

As Kit's compute: nthRoot 2 is the square root, 3 the cube root (real, so
negative values keep their sign), any other n is value ** (1 / n). A negative
value under any other root is NaN, as C's pow gives; nthRoot 0 raises to an
infinite power (inf above 1, 0 below, 1 at 1). Integer values give doubles.
"""
import math

from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._math import compute_binary

SPEC = NodeSpec(
    id="omni.graph.nodes.NthRoot",
    version=1,
    description=(
        "outputs:result = the nthRoot-th root of value, for each number of a scalar, vector, matrix or array: "
        "square root for 2, real cube root for 3 (negative values allowed), value ** (1 / nthRoot) otherwise; "
        "a negative value under an even or other non-cube root gives NaN, as Kit."),
    categories=("math:operator",),
    ui_name="Nth Root",
    inputs=(
        Attribute("nthRoot", "int", default=2, description="The degree of the root"),
        Attribute("value", "any", description="Number(s): a scalar, vector, matrix or array of them"),
    ),
    outputs=(
        Attribute("result", "any", description="The root(s), same shape, as doubles"),
    ),
)


def nth_root(value, n: int) -> float:
    """C's results for Kit's three cases: sqrt, cbrt and pow(value, 1 / n)."""
    value = float(value)
    if n == 3:      # the real cube root (C's cbrt; math.cbrt needs Python 3.11)
        return math.copysign(abs(value) ** (1.0 / 3.0), value)
    if value < 0.0:
        return math.nan
    if n == 2:
        return math.sqrt(value)
    exponent = math.copysign(math.inf, n) if n == 0 else 1.0 / n
    if value == 0.0 and exponent < 0.0:
        return math.inf
    return value ** exponent


def compute(db):
    compute_binary(db, nth_root, "result", names=("value", "nthRoot"))
