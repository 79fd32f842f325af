"""graphflow.QuaternionToEuler: a quaternion (x, y, z, w) to roll, pitch, yaw (radians)."""
import math

from graphflow.poses import quat_normalize
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="graphflow.QuaternionToEuler",
    version=1,
    description=("outputs:rotation = (roll, pitch, yaw) radians of inputs:quaternion (x, y, z, w), the inverse "
                 "of graphflow.EulerToQuaternion: roll and yaw in [-pi, pi], pitch in [-pi/2, pi/2]; yaw is "
                 "the heading about +Z (a prim's yaw from ReadPrimPose's orientation)."),
    categories=("math:conversion",),
    ui_name="Quaternion To Euler",
    inputs=(
        Attribute("quaternion", "quatd[4]", default=(0.0, 0.0, 0.0, 1.0), description="The rotation (x, y, z, w)"),
    ),
    outputs=(
        Attribute("rotation", "double[3]", description="(roll, pitch, yaw) in radians"),
        Attribute("yaw", "double", description="The yaw alone (radians)"),
    ),
)


def compute(db):
    x, y, z, w = quat_normalize(tuple(db.inputs.quaternion))
    roll = math.atan2(2.0 * (w * x + y * z), 1.0 - 2.0 * (x * x + y * y))
    pitch = math.asin(max(-1.0, min(1.0, 2.0 * (w * y - z * x))))
    yaw = math.atan2(2.0 * (w * z + x * y), 1.0 - 2.0 * (y * y + z * z))
    db.outputs.rotation = (roll, pitch, yaw)
    db.outputs.yaw = yaw
