"""isaacsim.robot.wheeled_robots.HolonomicController: wheel speeds of a mecanum (holonomic) base.

Isaac solves a quadratic program for the wheel speeds x: minimise
sum(r_i / |r| x_i^2) subject to the wheels producing the commanded planar
velocity, sum(d_i x_i) = (vx, vy), and yaw, sum(d_ix p_iy - d_iy p_ix) x_i = w,
where d_i = r_i times the wheel's axis turned by its orientation (w, x, y, z)
and by its mecanum angle (degrees, about upAxis) and p_i its position. With only
equality constraints that program has a closed-form minimum,
x = P^-1 A^T (A P^-1 A^T)^-1 b, computed here (Isaac's solver converges to it).
The command is first scaled by the gains and limited to maxLinearSpeed and
maxAngularSpeed; wheel speeds over maxWheelSpeed scale down together.
"""
import math

from graphflow.poses import quat_from_axis_angle, quat_normalize, quat_rotate
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState

SPEC = NodeSpec(
    id="isaacsim.robot.wheeled_robots.HolonomicController",
    version=2,
    compatible_versions=(1,),
    aliases=("omni.isaac.wheeled_robots.HolonomicController",),
    description=(
        "On execIn, turns inputVelocity (forward m/s, lateral m/s, yaw rad/s) into one velocity command per "
        "mecanum wheel (rad/s): the smallest wheel speeds (weighted by radius) that produce the command, as "
        "Isaac's quadratic program."),
    categories=("isaacWheeledRobots",),
    ui_name="Holonomic Controller",
    inputs=(
        Attribute("execIn", "execution", description="Compute the wheel commands"),
        Attribute("wheelRadius", "double[]", description="Wheel radii, m (one for all, or one per wheel)"),
        Attribute("wheelPositions", "double[3][]", description="Wheel positions from the chassis centre, m"),
        Attribute("wheelOrientations", "double[4][]",
                  description="Wheel orientations in the chassis frame, quaternions (w, x, y, z)"),
        Attribute("mecanumAngles", "double[]",
                  description="Roller angles about upAxis, degrees (as Isaac's controller reads them)"),
        Attribute("wheelAxis", "double[3]", default=(1.0, 0.0, 0.0), description="Wheel rotation axis"),
        Attribute("upAxis", "double[3]", default=(0.0, 0.0, 1.0), description="The vehicle's up axis"),
        Attribute("inputVelocity", "double[3]", default=(0.0, 0.0, 0.0),
                  description="Forward (m/s), lateral (m/s) and yaw (rad/s) velocity"),
        Attribute("maxLinearSpeed", "double", default=100000.0, description="Linear speed limit, m/s"),
        Attribute("maxAngularSpeed", "double", default=100000.0, description="Yaw rate limit, rad/s"),
        Attribute("maxWheelSpeed", "double", default=100000.0, description="Wheel speed limit, rad/s"),
        Attribute("linearGain", "double", default=1.0, description="Gain on the linear command"),
        Attribute("angularGain", "double", default=1.0, description="Gain on the yaw command"),
    ),
    outputs=(
        Attribute("execOut", "execution", description="Fires after the commands were computed"),
        Attribute("jointVelocityCommand", "double[]", description="Wheel velocity commands, rad/s"),
    ),
)


def compute(db):
    if db.inputs.execIn != ExecState.ENABLED:
        return
    inputs = db.inputs
    positions = inputs.wheelPositions
    count = len(positions)
    for name in ("wheelRadius", "wheelOrientations", "mecanumAngles"):
        if len(getattr(inputs, name)) not in ((1, count) if name != "wheelOrientations" else (count,)) or not count:
            db.error(f"inputs:{name} needs one entry per wheel (inputs:wheelPositions has {count})")
    radii = _per_wheel(inputs.wheelRadius, count)
    angles = _per_wheel(inputs.mecanumAngles, count)
    command = _limited(inputs)
    if all(abs(c) < 1e-8 for c in command):
        db.outputs.jointVelocityCommand = (0.0,) * count
        db.outputs.execOut = ExecState.ENABLED
        return
    rows = _constraints(inputs, positions, radii, angles)
    weights = _weights(radii)
    try:
        speeds = _least_weighted_norm(rows, weights, command)
    except ZeroDivisionError:
        db.error("the wheels cannot produce this motion (their directions are degenerate)")
    largest = max(abs(s) for s in speeds)
    if largest > inputs.maxWheelSpeed:
        speeds = [s * inputs.maxWheelSpeed / largest for s in speeds]
    db.outputs.jointVelocityCommand = tuple(speeds)
    db.outputs.execOut = ExecState.ENABLED


def _per_wheel(values, count):
    return [float(values[0])] * count if len(values) == 1 else [float(v) for v in values]


def _limited(inputs):
    vx, vy = inputs.inputVelocity[0] * inputs.linearGain, inputs.inputVelocity[1] * inputs.linearGain
    w = inputs.inputVelocity[2] * inputs.angularGain
    speed = math.hypot(vx, vy)
    if speed > inputs.maxLinearSpeed:
        vx, vy = vx * inputs.maxLinearSpeed / speed, vy * inputs.maxLinearSpeed / speed
    if abs(w) > inputs.maxAngularSpeed:
        w = math.copysign(inputs.maxAngularSpeed, w)
    return (vx, vy, w)


def _constraints(inputs, positions, radii, angles):
    """The three rows of A: each wheel's contribution to vx, vy and yaw per rad/s."""
    up = _unit(inputs.upAxis)
    rows = ([], [], [])
    for position, orientation, radius, angle in zip(positions, inputs.wheelOrientations, radii, angles):
        w, x, y, z = orientation
        axis = quat_rotate(quat_normalize((x, y, z, w)), inputs.wheelAxis)   # Isaac normalises it too
        axis = _unit(quat_rotate(quat_from_axis_angle(up, math.radians(angle)), axis))
        dx, dy = axis[0] * radius, axis[1] * radius
        rows[0].append(dx)
        rows[1].append(dy)
        rows[2].append(dx * position[1] - dy * position[0])
    return rows


def _weights(radii):
    norm = math.sqrt(sum(r * r for r in radii))
    return [r / norm for r in radii] if norm > 0 else [1.0] * len(radii)


def _least_weighted_norm(rows, weights, b):
    """x minimising sum(weights_i x_i^2) with rows . x = b: x = P^-1 A^T (A P^-1 A^T)^-1 b."""
    scaled = [[a / w for a, w in zip(row, weights)] for row in rows]          # A P^-1
    gram = [[sum(p * q for p, q in zip(row_s, row)) for row in rows] for row_s in scaled]
    multipliers = _solve3(gram, b)
    return [sum(scaled[k][i] * multipliers[k] for k in range(3)) for i in range(len(weights))]


def _solve3(m, b):
    """Solve the 3x3 system m y = b (Cramer's rule); ZeroDivisionError when m is singular."""
    def det(a):
        return (a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0])
                + a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]))
    whole = det(m)
    if abs(whole) < 1e-12:
        raise ZeroDivisionError
    return [det([[b[r] if c == k else m[r][c] for c in range(3)] for r in range(3)]) / whole for k in range(3)]


def _unit(v):
    norm = math.sqrt(sum(c * c for c in v))
    return tuple(c / norm for c in v) if norm > 0 else tuple(v)
