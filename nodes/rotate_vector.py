"""omni.graph.nodes.RotateVector: a direction vector turned by a quaternion (x, y, z, w)."""
from graphflow.poses import quat_normalize, quat_rotate
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.RotateVector",
    version=1,
    description=("outputs:result = inputs:vector rotated by inputs:rotation, a quaternion (x, y, z, w; normalised "
                 "here). OmniGraph also accepts Euler angles and matrices for rotation; graphflow takes "
                 "quaternions (graphflow.EulerToQuaternion makes one)."),
    categories=("math:operator",),
    ui_name="Rotate Vector",
    inputs=(
        Attribute("rotation", "quatd[4]", default=(0.0, 0.0, 0.0, 1.0), description="The rotation (x, y, z, w)"),
        Attribute("vector", "double[3]", default=(0.0, 0.0, 0.0), description="The vector to rotate"),
    ),
    outputs=(
        Attribute("result", "double[3]", description="The rotated vector"),
    ),
)


def compute(db):
    db.outputs.result = quat_rotate(quat_normalize(tuple(db.inputs.rotation)), tuple(db.inputs.vector))
