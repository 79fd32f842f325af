"""omni.graph.nodes.MatrixMultiply: the product A*B of matrices and vectors (A's tuples rows, B's columns)."""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._matrices import SIZES, MatrixError, each, multiply, numbers

SPEC = NodeSpec(
    id="omni.graph.nodes.MatrixMultiply",
    version=1,
    description=(
        "outputs:output = a * b. 3x3 and 4x4 matrices are 9 and 16 values row by row; shorter tuples are "
        "vectors, a row vector in a and a column vector in b (vector * vector is their dot product). A 2x2 "
        "matrix cannot be told from a 4-vector by value and multiplies as a vector. Arrays elementwise, a "
        "single operand repeated over an array."),
    categories=("math:operator",),
    ui_name="Matrix Multiply",
    inputs=(
        Attribute("a", "any", description="First matrix or row vector, multiplied as a*b"),
        Attribute("b", "any", description="Second matrix or column vector"),
    ),
    outputs=(
        Attribute("output", "any", description="The product a*b"),
    ),
)


def _product(a, b):
    a, b = numbers(a, "a"), numbers(b, "b")
    na, nb = SIZES.get(len(a)) if len(a) in (9, 16) else None, SIZES.get(len(b)) if len(b) in (9, 16) else None
    if na and nb and na == nb:
        return multiply(a, b, na)
    if na is None and nb and len(a) == nb:         # row vector * matrix
        return tuple(sum(a[k] * b[nb * k + j] for k in range(nb)) for j in range(nb))
    if na and nb is None and len(b) == na:         # matrix * column vector
        return tuple(sum(a[na * i + k] * b[k] for k in range(na)) for i in range(na))
    if na is None and nb is None and len(a) == len(b):
        return sum(x * y for x, y in zip(a, b))
    raise MatrixError(f"cannot multiply {len(a)} values (inputs:a) by {len(b)} values (inputs:b)")


def compute(db):
    if db.inputs.a is None or db.inputs.b is None:
        db.error("inputs:a and inputs:b need values; connect them or set values")
    try:
        db.outputs.output = each(_product, db.inputs.a, db.inputs.b)
    except MatrixError as error:
        db.error(str(error))
