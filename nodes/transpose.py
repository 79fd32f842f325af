"""omni.graph.nodes.Transpose: a matrix flipped over its diagonal."""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._matrices import MatrixError, each, numbers, side, transpose

SPEC = NodeSpec(
    id="omni.graph.nodes.Transpose",
    version=1,
    description="outputs:result = the transpose of matrix (2x2, 3x3 or 4x4, row by row); arrays matrix by matrix.",
    categories=("math:operator",),
    ui_name="Transpose",
    inputs=(
        Attribute("matrix", "any", description="A matrix (4, 9 or 16 values) or an array of them"),
    ),
    outputs=(
        Attribute("result", "any", description="The transposed matrix or matrices"),
    ),
)


def compute(db):
    if db.inputs.matrix is None:
        db.error("inputs:matrix has no value; connect it or set a value")
    try:
        db.outputs.result = each(lambda m: transpose(numbers(m, "matrix"), side(m, "matrix")), db.inputs.matrix)
    except MatrixError as error:
        db.error(str(error))
