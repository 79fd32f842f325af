"""omni.graph.nodes.SetMatrix4Scale: a 3x3 or 4x4 transform with its scale replaced."""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._matrices import MatrixError, numbers, rotation_only, side, upper3, with_upper3

SPEC = NodeSpec(
    id="omni.graph.nodes.SetMatrix4Scale",
    version=1,
    description=(
        "outputs:matrix = matrix with its axes (the first three rows' first three values) rescaled to the "
        "lengths in scale: the rotation and translation are kept."),
    categories=("math:operator",),
    ui_name="Set Scale",
    inputs=(
        Attribute("matrix", "any", description="A 3x3 or 4x4 matrix (9 or 16 values)"),
        Attribute("scale", "vectord[3]", default=(1.0, 1.0, 1.0), description="The new scale along X, Y and Z"),
    ),
    outputs=(
        Attribute("matrix", "any", description="The updated matrix"),
    ),
)


def compute(db):
    if db.inputs.matrix is None:
        db.error("inputs:matrix has no value; connect it or set a value")
    try:
        m = numbers(db.inputs.matrix, "matrix")
        n = side(m, "matrix", (3, 4))
    except MatrixError as error:
        db.error(str(error))
    rotation, scale = rotation_only(upper3(m, n)), db.inputs.scale
    db.outputs.matrix = with_upper3(m, n, tuple(scale[i] * rotation[3 * i + j] for i in range(3) for j in range(3)))
