"""omni.graph.nodes.GetMatrix4Rotation: the Euler angles (degrees) of a transform's or quaternion's rotation."""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._matrices import ORDERS, MatrixError, each, matrix_euler, rotation_of

SPEC = NodeSpec(
    id="omni.graph.nodes.GetMatrix4Rotation",
    version=2,
    description=(
        "outputs:rotation = the Euler angles in degrees about X, Y and Z that, applied in rotationOrder as USD's "
        "xformOp:rotate<ORDER>, give the rotation of matrix (3x3 or 4x4, scale divided out) or of a quaternion "
        "(x, y, z, w). The middle axis's angle is within [-90, 90]; arrays elementwise."),
    categories=("math:operator",),
    ui_name="Get Rotation",
    inputs=(
        Attribute("matrix", "any", description="A 3x3 or 4x4 matrix (9 or 16 values) or a quaternion (4 values)"),
        Attribute("rotationOrder", "token", default="XYZ", allowed_tokens=ORDERS,
                  description="The order of the output rotation angles"),
    ),
    outputs=(
        Attribute("rotation", "any", description="Euler angles in degrees (vectord[3])"),
    ),
)


def compute(db):
    if db.inputs.matrix is None:
        db.error("inputs:matrix has no value; connect it or set a value")
    try:
        db.outputs.rotation = each(lambda m: matrix_euler(rotation_of(m), db.inputs.rotationOrder), db.inputs.matrix)
    except MatrixError as error:
        db.error(str(error))
