"""omni.graph.nodes.MakeMatrix3: a 3x3 matrix from its rows."""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._matrices import MatrixError, each, numbers

SPEC = NodeSpec(
    id="omni.graph.nodes.MakeMatrix3",
    version=1,
    description=(
        "outputs:matrix = the 3x3 matrix whose rows are x, y, z (9 values row by row)"
        "; arrays of rows give an array of matrices."),
    categories=("math:conversion",),
    ui_name="Make Matrix3",
    inputs=(
        Attribute("x", "any", description="The first row (double[3])"),
        Attribute("y", "any", description="The second row (double[3])"),
        Attribute("z", "any", description="The third row (double[3])"),
    ),
    outputs=(
        Attribute("matrix", "any", description="The matrix formed by the rows"),
    ),
)


def _row(value, name, last):
    row = numbers(value, name)
    if len(row) != 3:
        raise MatrixError(f"inputs:{name} must have 3 values, got {len(row)}")
    return row


def _matrix(*values):
    return tuple(c for i, value in enumerate(values) for c in _row(value, "xyz"[i], i == 3))


def compute(db):
    values = [getattr(db.inputs, name) for name in "xyz"]
    if any(value is None for value in values):
        db.error("inputs:x, inputs:y, inputs:z all need values; connect them or set values")
    try:
        db.outputs.matrix = each(_matrix, *values)
    except MatrixError as error:
        db.error(str(error))
