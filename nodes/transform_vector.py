"""omni.graph.nodes.TransformVector: a row vector times a 3x3 or 4x4 matrix."""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._matrices import MatrixError, each, numbers, side

SPEC = NodeSpec(
    id="omni.graph.nodes.TransformVector",
    version=1,
    description=(
        "outputs:result = vector * matrix (a row vector). With a 4x4 matrix the 3-vector is a point: its "
        "fourth component is 1 and the result is divided by the fourth component of the product, so the "
        "translation applies. Arrays elementwise, a single matrix or vector repeated over an array."),
    categories=("math:operator",),
    ui_name="Transform Vector",
    inputs=(
        Attribute("matrix", "any", description="A 3x3 or 4x4 matrix (9 or 16 values), or an array of them"),
        Attribute("vector", "any", description="A 3-vector, or an array of them"),
    ),
    outputs=(
        Attribute("result", "any", description="The transformed vector(s)"),
    ),
)


def _transform(matrix, vector):
    m, v = numbers(matrix, "matrix"), numbers(vector, "vector")
    n = side(m, "matrix", (3, 4))
    if len(v) != 3:
        raise MatrixError(f"inputs:vector must have 3 values, got {len(v)}")
    row = v + (1.0,) if n == 4 else v
    product = [sum(row[k] * m[n * k + j] for k in range(n)) for j in range(n)]
    if n == 3:
        return tuple(product)
    w = product[3] or 1.0
    return tuple(c / w for c in product[:3])


def compute(db):
    if db.inputs.matrix is None or db.inputs.vector is None:
        db.error("inputs:matrix and inputs:vector need values; connect them or set values")
    try:
        db.outputs.result = each(_transform, db.inputs.matrix, db.inputs.vector)
    except MatrixError as error:
        db.error(str(error))
