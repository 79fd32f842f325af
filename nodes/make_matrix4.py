"""omni.graph.nodes.MakeMatrix4: a 4x4 matrix from its rows."""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._matrices import MatrixError, each, numbers

SPEC = NodeSpec(
    id="omni.graph.nodes.MakeMatrix4",
    version=1,
    description=(
        "outputs:matrix = the 4x4 matrix whose rows are x, y, z, w (16 values row by row); a 3-value row gets "
        "a fourth column of 0 (1 for w, the translation row); arrays of rows give an array of matrices."),
    categories=("math:conversion",),
    ui_name="Make Matrix4",
    inputs=(
        Attribute("x", "any", description="The first row (double[4], or double[3])"),
        Attribute("y", "any", description="The second row (double[4], or double[3])"),
        Attribute("z", "any", description="The third row (double[4], or double[3])"),
        Attribute("w", "any", description="The fourth row (double[4], or double[3])"),
    ),
    outputs=(
        Attribute("matrix", "any", description="The matrix formed by the rows"),
    ),
)


def _row(value, name, last):
    row = numbers(value, name)
    if len(row) == 3:   # a 3-vector row: the affine column added (0, or 1 in the translation row)
        return row + ((1.0 if last else 0.0),)
    if len(row) != 4:
        raise MatrixError(f"inputs:{name} must have 3 or 4 values, got {len(row)}")
    return row


def _matrix(*values):
    return tuple(c for i, value in enumerate(values) for c in _row(value, "xyzw"[i], i == 3))


def compute(db):
    values = [getattr(db.inputs, name) for name in "xyzw"]
    if any(value is None for value in values):
        db.error("inputs:x, inputs:y, inputs:z, inputs:w all need values; connect them or set values")
    try:
        db.outputs.matrix = each(_matrix, *values)
    except MatrixError as error:
        db.error(str(error))
