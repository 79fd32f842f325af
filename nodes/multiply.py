"""omni.graph.nodes.Multiply: a * b, elementwise."""
import operator

from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._math import MathError, compute_binary

SPEC = NodeSpec(
    id="omni.graph.nodes.Multiply",
    version=2,
    compatible_versions=(1,),
    description=(
        "outputs:product = a * b, for numbers, tuples (double[3]) and arrays, "
        "elementwise; a scalar (or a tuple against an array of tuples) is broadcast. "
        "Integers stay integers when both operands are integers."),
    categories=("math:operator",),
    ui_name="Multiply",
    inputs=(
        Attribute("a", "any", description="First operand (number, tuple or array)"),
        Attribute("b", "any", description="Second operand (number, tuple or array)"),
    ),
    outputs=(
        Attribute("product", "any", description="a * b, elementwise"),
    ),
)


INTEGER_RANGE = (-(2**63), 2**64)   # what int64 / uint64 hold; Python's own ints never overflow


def _multiply(a, b):
    """a * b; an integer product beyond 64 bits is an error (squaring a variable every tick would
    otherwise grow it to millions of digits and slow every tick down to a halt)."""
    product = operator.mul(a, b)
    if type(product) is int and not INTEGER_RANGE[0] <= product < INTEGER_RANGE[1]:
        raise MathError(f"integer overflow: the product of {a.bit_length()}-bit and {b.bit_length()}-bit "
                        f"integers does not fit 64 bits")
    return product


def compute(db):
    compute_binary(db, _multiply, "product")
