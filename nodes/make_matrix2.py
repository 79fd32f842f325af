"""omni.graph.nodes.MakeMatrix2: a 2x2 matrix from its rows."""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._matrices import MatrixError, each, numbers

SPEC = NodeSpec(
    id="omni.graph.nodes.MakeMatrix2",
    version=1,
    description=(
        "outputs:matrix = the 2x2 matrix whose rows are x, y (4 values row by row)"
        "; arrays of rows give an array of matrices."),
    categories=("math:conversion",),
    ui_name="Make Matrix2",
    inputs=(
        Attribute("x", "any", description="The first row (double[2])"),
        Attribute("y", "any", description="The second row (double[2])"),
    ),
    outputs=(
        Attribute("matrix", "any", description="The matrix formed by the rows"),
    ),
)


def _row(value, name, last):
    row = numbers(value, name)
    if len(row) != 2:
        raise MatrixError(f"inputs:{name} must have 2 values, got {len(row)}")
    return row


def _matrix(*values):
    return tuple(c for i, value in enumerate(values) for c in _row(value, "xy"[i], i == 3))


def compute(db):
    values = [getattr(db.inputs, name) for name in "xy"]
    if any(value is None for value in values):
        db.error("inputs:x, inputs:y all need values; connect them or set values")
    try:
        db.outputs.matrix = each(_matrix, *values)
    except MatrixError as error:
        db.error(str(error))
