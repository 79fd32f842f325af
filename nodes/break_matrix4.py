"""omni.graph.nodes.BreakMatrix4: the rows of a 4x4 matrix."""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._matrices import MatrixError, each, numbers, rows, side

SPEC = NodeSpec(
    id="omni.graph.nodes.BreakMatrix4",
    version=1,
    description=(
        "outputs:x, outputs:y, outputs:z, outputs:w = the rows of matrix (16 values row by row); outputType double[3] drops each row's last value; an "
        "array of matrices gives arrays of rows."),
    categories=("math:conversion",),
    ui_name="Break Matrix4",
    inputs=(
        Attribute("matrix", "any", description="A 4x4 matrix or an array of them"),
        Attribute("outputType", "token", default="double[4]", allowed_tokens=("double[3]", "double[4]"),
                  description="double[4] rows, or double[3] (each row's last value dropped)"),
    ),
    outputs=(
        Attribute("x", "any", description="The first row of the matrix"),
        Attribute("y", "any", description="The second row of the matrix"),
        Attribute("z", "any", description="The third row of the matrix"),
        Attribute("w", "any", description="The fourth row of the matrix"),
    ),
)


def compute(db):
    if db.inputs.matrix is None:
        db.error("inputs:matrix has no value; connect it or set a value")
    keep = 3 if db.inputs.outputType == "double[3]" else 4
    try:
        broken = each(lambda m: tuple(row[:keep] for row in rows(numbers(m, "matrix"), side(m, "matrix", (4,)))),
                      db.inputs.matrix)
    except MatrixError as error:
        db.error(str(error))
    single = not isinstance(broken[0][0], tuple)
    for i, name in enumerate("xyzw"):
        setattr(db.outputs, name, broken[i] if single else tuple(m[i] for m in broken))
