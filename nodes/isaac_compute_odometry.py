"""isaacsim.core.nodes.IsaacComputeOdometry: odometry of a chassis from the world, as Isaac computes it.

The first compute after a reset takes the chassis pose as the odometry frame:
position is the displacement since then in that start frame, orientation the
rotation since then (q_start^-1 q). linearVelocity is the world velocity in the
chassis frame, globalLinearVelocity and angularVelocity are world-frame; the
accelerations are the change of those velocities over the time since the last
compute (zero until a second compute at a later time).
"""
from graphflow.poses import quat_conjugate, quat_multiply, quat_rotate
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState
from graphflow.world import WorldError

ZERO = (0.0, 0.0, 0.0)

SPEC = NodeSpec(
    id="isaacsim.core.nodes.IsaacComputeOdometry",
    version=1,
    aliases=("omni.isaac.core_nodes.IsaacComputeOdometry",),
    description=(
        "On execIn, the odometry of chassisPrim (an articulation root or rigid body) relative to its pose at "
        "the first compute: position (m) and orientation in that start frame, velocities (m/s, rad/s) and "
        "accelerations (finite differences between computes); linear ones in the chassis frame, global ones "
        "and the angular ones in the world frame."),
    categories=("isaacCore",),
    ui_name="Isaac Compute Odometry Node",
    inputs=(
        Attribute("execIn", "execution", description="Compute the odometry"),
        Attribute("chassisPrim", "target", description="The articulation root or rigid body of the chassis"),
    ),
    outputs=(
        Attribute("execOut", "execution", description="Fires after the odometry was computed"),
        Attribute("position", "vectord[3]", description="Displacement since the start, in the start frame, m"),
        Attribute("orientation", "quatd[4]", default=(0.0, 0.0, 0.0, 1.0),
                  description="Rotation since the start (x, y, z, w)"),
        Attribute("linearVelocity", "vectord[3]", description="Linear velocity in the chassis frame, m/s"),
        Attribute("angularVelocity", "vectord[3]", description="Angular velocity, world frame, rad/s"),
        Attribute("linearAcceleration", "vectord[3]", description="Linear acceleration in the chassis frame, m/s^2"),
        Attribute("angularAcceleration", "vectord[3]", description="Angular acceleration, world frame, rad/s^2"),
        Attribute("globalLinearVelocity", "vectord[3]", description="Linear velocity, world frame, m/s"),
        Attribute("globalLinearAcceleration", "vectord[3]", description="Linear acceleration, world frame, m/s^2"),
    ),
)


def compute(db):
    if db.inputs.execIn != ExecState.ENABLED:
        return
    if not db.inputs.chassisPrim:
        db.error("inputs:chassisPrim is not set: no chassis to follow")
    path = db.inputs.chassisPrim[0]
    try:
        position, orientation = db.world.prim_pose(path)
        world_linear, angular = db.world.prim_velocity(path)
    except WorldError as error:
        db.error(f"inputs:chassisPrim: {error}")
    state = db.internal
    if "start" not in state:
        state["start"] = (tuple(position), tuple(orientation))
    start_position, start_orientation = state["start"]
    inverse_start = quat_conjugate(start_orientation)
    local_linear = quat_rotate(quat_conjugate(orientation), world_linear)
    previous = state.get("previous")
    if previous is not None and db.time != previous[0]:
        elapsed = db.time - previous[0]
        db.outputs.linearAcceleration = _rate(local_linear, previous[1], elapsed)
        db.outputs.globalLinearAcceleration = _rate(world_linear, previous[2], elapsed)
        db.outputs.angularAcceleration = _rate(angular, previous[3], elapsed)
    state["previous"] = (db.time, local_linear, tuple(world_linear), tuple(angular))
    displacement = tuple(p - s for p, s in zip(position, start_position))
    db.outputs.position = quat_rotate(inverse_start, displacement)
    db.outputs.orientation = quat_multiply(inverse_start, orientation)
    db.outputs.linearVelocity = local_linear
    db.outputs.globalLinearVelocity = tuple(float(v) for v in world_linear)
    db.outputs.angularVelocity = tuple(float(v) for v in angular)
    db.outputs.execOut = ExecState.ENABLED


def _rate(now, before, elapsed: float):
    return tuple((a - b) / elapsed for a, b in zip(now, before))
