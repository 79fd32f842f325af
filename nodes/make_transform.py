"""omni.graph.nodes.MakeTransform: a 4x4 transform from translation, Euler rotation and scale."""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._matrices import ORDERS, MatrixError, euler_matrix

SPEC = NodeSpec(
    id="omni.graph.nodes.MakeTransform",
    version=2,
    description=(
        "outputs:transform = scale, then rotate by rotationXYZ (degrees about X, Y, Z, applied in rotationOrder "
        "as USD's xformOp:rotate<ORDER>), then translate: the USD matrix S * R * T for row vectors."),
    categories=("math:operator",),
    ui_name="Make Transformation Matrix from TRS",
    inputs=(
        Attribute("rotationOrder", "token", default="XYZ", allowed_tokens=ORDERS,
                  description="The order the rotations are applied in"),
        Attribute("rotationXYZ", "vectord[3]", default=(0.0, 0.0, 0.0),
                  description="Euler angles about X, Y and Z, in degrees"),
        Attribute("scale", "vectord[3]", default=(1.0, 1.0, 1.0), description="Scale along X, Y and Z"),
        Attribute("translation", "vectord[3]", default=(0.0, 0.0, 0.0), description="The translation"),
    ),
    outputs=(
        Attribute("transform", "matrixd[16]", description="The transformation matrix"),
    ),
)


def compute(db):
    try:
        rotation = euler_matrix(db.inputs.rotationXYZ, db.inputs.rotationOrder)
    except MatrixError as error:
        db.error(str(error))
    scale, t = db.inputs.scale, db.inputs.translation
    db.outputs.transform = tuple(
        c for i in range(3) for c in (*(scale[i] * rotation[3 * i + j] for j in range(3)), 0.0)) + (
        float(t[0]), float(t[1]), float(t[2]), 1.0)
