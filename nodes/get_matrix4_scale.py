"""omni.graph.nodes.GetMatrix4Scale: the scale along each axis of a 3x3 or 4x4 transform."""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._matrices import MatrixError, each, numbers, row_lengths, side, upper3

SPEC = NodeSpec(
    id="omni.graph.nodes.GetMatrix4Scale",
    version=1,
    description=(
        "outputs:scale = the lengths of the first three rows' first three values (the scaled X, Y, Z axes) "
        "of matrix; arrays matrix by matrix."),
    categories=("math:operator",),
    ui_name="Get Scale",
    inputs=(
        Attribute("matrix", "any", description="A 3x3 or 4x4 matrix (9 or 16 values), or an array of them"),
    ),
    outputs=(
        Attribute("scale", "any", description="The scale along X, Y and Z (vectord[3])"),
    ),
)


def compute(db):
    if db.inputs.matrix is None:
        db.error("inputs:matrix has no value; connect it or set a value")
    try:
        db.outputs.scale = each(lambda m: row_lengths(upper3(numbers(m, "matrix"), side(m, "matrix", (3, 4)))),
                                db.inputs.matrix)
    except MatrixError as error:
        db.error(str(error))
