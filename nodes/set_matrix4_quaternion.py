"""omni.graph.nodes.SetMatrix4Quaternion: a 4x4 transform with its rotation replaced."""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._vectors import IDENTITY, matrix_translation, pose_matrix

SPEC = NodeSpec(
    id="omni.graph.nodes.SetMatrix4Quaternion",
    version=1,
    description=(
        "outputs:matrix = matrix with its rotation set to quaternion (x, y, z, w); the translation (row 3) is "
        "kept. Any scale of the input matrix is not kept."),
    categories=("math:operator",),
    ui_name="Set Rotation Quaternion",
    inputs=(
        Attribute("matrix", "matrixd[16]", default=IDENTITY, description="The matrix to be modified"),
        Attribute("quaternion", "quatd[4]", default=(0.0, 0.0, 0.0, 1.0), description="The new rotation"),
    ),
    outputs=(
        Attribute("matrix", "matrixd[16]", description="The updated matrix"),
    ),
)


def compute(db):
    db.outputs.matrix = pose_matrix(matrix_translation(db.inputs.matrix), db.inputs.quaternion)
