"""omni.graph.nodes.SetMatrix4Rotation: a 4x4 transform with its rotation replaced (angle, Euler, quaternion, matrix)."""
import math

from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._matrices import (
    ORDERS,
    MatrixError,
    euler_matrix,
    numbers,
    quaternion_matrix,
    row_lengths,
    upper3,
    with_upper3,
)
from graphflow_nodes._vectors import IDENTITY

SPEC = NodeSpec(
    id="omni.graph.nodes.SetMatrix4Rotation",
    version=2,
    description=(
        "outputs:matrix = matrix with its rotation set by rotationAngle, keeping its translation (row 3) and the "
        "scale of each axis: a number is an angle in degrees about fixedRotationAxis (Custom: rotationAxis), "
        "3 values are Euler angles in degrees applied in rotationOrder as USD's xformOp:rotate<ORDER>, 4 a "
        "quaternion (x, y, z, w), 9 a 3x3 rotation matrix row by row."),
    categories=("math:operator",),
    ui_name="Set Rotation",
    inputs=(
        Attribute("fixedRotationAxis", "token", default="Y", allowed_tokens=("X", "Y", "Z", "Custom"),
                  description="The axis an angle turns about"),
        Attribute("matrix", "matrixd[16]", default=IDENTITY, description="The matrix to be modified"),
        Attribute("rotationAngle", "any", description="An angle, Euler angles, a quaternion or a rotation matrix"),
        Attribute("rotationAxis", "vectord[3]", default=(0.0, 1.0, 0.0),
                  description="The axis of rotation when fixedRotationAxis is Custom"),
        Attribute("rotationOrder", "token", default="XYZ", allowed_tokens=ORDERS,
                  description="The order Euler angles are applied in"),
    ),
    outputs=(
        Attribute("matrix", "matrixd[16]", description="The updated matrix"),
    ),
)


def _axis_angle(axis, degrees: float) -> tuple[float, ...]:
    """The 3x3 row-vector matrix turning by *degrees* about *axis* (normalised)."""
    norm = math.sqrt(sum(c * c for c in axis))
    if norm == 0.0:
        raise MatrixError("inputs:rotationAxis is zero: no axis to turn about")
    x, y, z = (c / norm for c in axis)
    half = math.radians(degrees) / 2.0
    return quaternion_matrix((x * math.sin(half), y * math.sin(half), z * math.sin(half), math.cos(half)))


def _rotation(db) -> tuple[float, ...]:
    value = db.inputs.rotationAngle
    if value is None:
        raise MatrixError("inputs:rotationAngle has no value; connect it or set a value")
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        fixed = db.inputs.fixedRotationAxis
        axis = db.inputs.rotationAxis if fixed == "Custom" else tuple(float(c == fixed) for c in "XYZ")
        return _axis_angle(axis, float(value))
    values = numbers(value, "rotationAngle")
    if len(values) == 3:
        return euler_matrix(values, db.inputs.rotationOrder)
    if len(values) == 4:
        return quaternion_matrix(values)
    if len(values) == 9:
        return values
    raise MatrixError(f"inputs:rotationAngle must be an angle or 3, 4 or 9 values, got {len(values)} values")


def compute(db):
    try:
        rotation = _rotation(db)
    except MatrixError as error:
        db.error(str(error))
    scale = row_lengths(upper3(db.inputs.matrix, 4))
    db.outputs.matrix = with_upper3(db.inputs.matrix, 4,
                                    tuple(scale[i] * rotation[3 * i + j] for i in range(3) for j in range(3)))
