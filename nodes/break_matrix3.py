"""omni.graph.nodes.BreakMatrix3: the rows of a 3x3 matrix."""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._matrices import MatrixError, each, numbers, rows, side

SPEC = NodeSpec(
    id="omni.graph.nodes.BreakMatrix3",
    version=1,
    description=(
        "outputs:x, outputs:y, outputs:z = the rows of matrix (9 values row by row); an "
        "array of matrices gives arrays of rows."),
    categories=("math:conversion",),
    ui_name="Break Matrix3",
    inputs=(
        Attribute("matrix", "any", description="A 3x3 matrix or an array of them"),
    ),
    outputs=(
        Attribute("x", "any", description="The first row of the matrix"),
        Attribute("y", "any", description="The second row of the matrix"),
        Attribute("z", "any", description="The third row of the matrix"),
    ),
)


def compute(db):
    if db.inputs.matrix is None:
        db.error("inputs:matrix has no value; connect it or set a value")
    keep = 3
    try:
        broken = each(lambda m: tuple(row[:keep] for row in rows(numbers(m, "matrix"), side(m, "matrix", (3,)))),
                      db.inputs.matrix)
    except MatrixError as error:
        db.error(str(error))
    single = not isinstance(broken[0][0], tuple)
    for i, name in enumerate("xyz"):
        setattr(db.outputs, name, broken[i] if single else tuple(m[i] for m in broken))
