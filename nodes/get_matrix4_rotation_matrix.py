"""omni.graph.nodes.GetMatrix4RotationMatrix: the 3x3 rotation of a transform, quaternion or Euler angles."""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._matrices import ORDERS, MatrixError, each, euler_matrix, numbers, quaternion_matrix, rotation_of

SPEC = NodeSpec(
    id="omni.graph.nodes.GetMatrix4RotationMatrix",
    version=1,
    description=(
        "outputs:rotation = the 3x3 rotation (9 values row by row) of matrix: a 4x4 transform (scale divided "
        "out), a quaternion (x, y, z, w) or Euler angles in degrees about X, Y, Z applied in rotationOrder as "
        "USD's xformOp:rotate<ORDER>; arrays elementwise."),
    categories=("math:operator",),
    ui_name="Get Rotation Matrix",
    inputs=(
        Attribute("matrix", "any", description="A 4x4 matrix (16 values), a quaternion (4) or Euler angles (3)"),
        Attribute("rotationOrder", "token", default="XYZ", allowed_tokens=ORDERS,
                  description="The order Euler angles are applied in"),
    ),
    outputs=(
        Attribute("rotation", "any", description="The rotation as a 3x3 matrix (matrixd[3])"),
    ),
)


def _rotation(value, order):
    values = numbers(value, "matrix")
    if len(values) == 3:
        return euler_matrix(values, order)
    if len(values) == 4:
        return quaternion_matrix(values)
    if len(values) != 16:
        raise MatrixError(f"inputs:matrix must be a 4x4 matrix, a quaternion or Euler angles, got {len(values)} values")
    return rotation_of(values)


def compute(db):
    if db.inputs.matrix is None:
        db.error("inputs:matrix has no value; connect it or set a value")
    try:
        db.outputs.rotation = each(lambda m: _rotation(m, db.inputs.rotationOrder), db.inputs.matrix)
    except MatrixError as error:
        db.error(str(error))
