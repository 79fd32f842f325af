"""graphflow.EulerToQuaternion: roll, pitch, yaw (radians) to a quaternion (x, y, z, w)."""
import math

from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="graphflow.EulerToQuaternion",
    version=1,
    description=("outputs:quaternion turns by inputs:rotation = (roll, pitch, yaw) radians: about the fixed X "
                 "axis, then the fixed Y, then the fixed Z (the yaw is the heading about +Z). Quaternions are "
                 "(x, y, z, w), as OmniGraph's quatd[4]."),
    categories=("math:conversion",),
    ui_name="Euler To Quaternion",
    inputs=(
        Attribute("rotation", "double[3]", default=(0.0, 0.0, 0.0), description="(roll, pitch, yaw) in radians"),
    ),
    outputs=(
        Attribute("quaternion", "quatd[4]", description="The same rotation as (x, y, z, w)"),
    ),
)


def compute(db):
    roll, pitch, yaw = (0.5 * float(a) for a in db.inputs.rotation)
    cr, sr, cp, sp, cy, sy = (math.cos(roll), math.sin(roll), math.cos(pitch), math.sin(pitch),
                              math.cos(yaw), math.sin(yaw))
    db.outputs.quaternion = (sr * cp * cy - cr * sp * sy,
                             cr * sp * cy + sr * cp * sy,
                             cr * cp * sy - sr * sp * cy,
                             cr * cp * cy + sr * sp * sy)
