"""omni.graph.nodes.GetMatrix4Quaternion: the rotation of a 4x4 transform, as a quaternion."""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._vectors import matrix_quaternion

SPEC = NodeSpec(
    id="omni.graph.nodes.GetMatrix4Quaternion",
    version=1,
    description=(
        "outputs:quaternion = the rotation (x, y, z, w) of matrix, a USD 4x4 transform (row vectors, 16 "
        "values row by row), with any scale divided out."),
    categories=("math:operator",),
    ui_name="Get Rotation Quaternion",
    inputs=(
        Attribute("matrix", "matrixd[16]", default=(1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0,
                                                   0.0, 0.0, 0.0, 1.0), description="The transformation matrix"),
    ),
    outputs=(
        Attribute("quaternion", "quatd[4]", description="The matrix's rotation (x, y, z, w)"),
    ),
)


def compute(db):
    db.outputs.quaternion = matrix_quaternion(db.inputs.matrix)
