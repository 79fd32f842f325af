"""Serial-arm kinematics: forward kinematics, Jacobian, damped-least-squares IK.

Controllers plan on this kinematic copy of the robot, never on the simulated
one, so solving IK cannot disturb the physics state (PyBullet's own IK works
on the live body and needs its state set and restored; pybullet_notes §3d).

Frames follow URDF: each joint has a fixed origin (xyz, rpy) in its parent
link and an axis in the joint frame; the child link frame is the joint frame
rotated by the joint angle. Quaternions are (x, y, z, w).
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING, Sequence

from graphflow.poses import quat_matrix, quat_normalize

if TYPE_CHECKING:
    import numpy as np

DEFAULT_POSITION_TOLERANCE = 1e-5     # m: 100x below the 1 mm the controllers need
DEFAULT_ORIENTATION_TOLERANCE = 1e-4  # rad
DEFAULT_MAX_ITERATIONS = 200
DAMPING = 0.02                        # damped least squares: lambda (m, rad), keeps steps finite near singularities
MAX_JOINT_STEP = 0.3                  # rad per iteration: Newton steps far from the solution can overshoot


def quaternion_to_matrix(quaternion: Sequence[float]) -> "np.ndarray":
    return _matrix(_quaternion_rotation(quaternion))


def matrix_to_quaternion(matrix) -> tuple[float, float, float, float]:
    m = matrix
    trace = m[0, 0] + m[1, 1] + m[2, 2]
    if trace > 0:
        s = 2.0 * math.sqrt(trace + 1.0)
        q = ((m[2, 1] - m[1, 2]) / s, (m[0, 2] - m[2, 0]) / s, (m[1, 0] - m[0, 1]) / s, 0.25 * s)
    elif m[0, 0] > m[1, 1] and m[0, 0] > m[2, 2]:
        s = 2.0 * math.sqrt(1.0 + m[0, 0] - m[1, 1] - m[2, 2])
        q = (0.25 * s, (m[0, 1] + m[1, 0]) / s, (m[0, 2] + m[2, 0]) / s, (m[2, 1] - m[1, 2]) / s)
    elif m[1, 1] > m[2, 2]:
        s = 2.0 * math.sqrt(1.0 + m[1, 1] - m[0, 0] - m[2, 2])
        q = ((m[0, 1] + m[1, 0]) / s, 0.25 * s, (m[1, 2] + m[2, 1]) / s, (m[0, 2] - m[2, 0]) / s)
    else:
        s = 2.0 * math.sqrt(1.0 + m[2, 2] - m[0, 0] - m[1, 1])
        q = ((m[0, 2] + m[2, 0]) / s, (m[1, 2] + m[2, 1]) / s, 0.25 * s, (m[1, 0] - m[0, 1]) / s)
    return tuple(float(c) for c in q)  # type: ignore[return-value]


def rotation_error(target, current) -> "np.ndarray":
    """The rotation vector (axis * angle, world frame) that turns *current* into *target* (3x3 arrays)."""
    import numpy as np

    return np.array(_rotation_error(_flat(target), _flat(current)))


@dataclass(frozen=True)
class Joint:
    name: str
    xyz: tuple[float, float, float]
    rpy: tuple[float, float, float]
    axis: tuple[float, float, float]
    lower: float
    upper: float
    rotation: tuple[float, ...] | None = None   # the origin's rotation as a row-major 3x3 (instead of rpy)


@dataclass(frozen=True)
class IKSolution:
    positions: tuple[float, ...]
    position_error: float        # m, at the tool point
    orientation_error: float     # rad
    iterations: int
    converged: bool


class SerialChain:
    """A fixed-base chain of revolute joints ending in a tool frame (all in the base frame).

    The solver works on plain floats (rotations as row-major 9-tuples): for 3x3
    and 6x6 arithmetic numpy's per-call overhead costs far more than the
    arithmetic, and the controllers solve on every tick.
    """

    def __init__(self, joints: Sequence[Joint], tool_xyz=(0.0, 0.0, 0.0), tool_rpy=(0.0, 0.0, 0.0),
                 tool_rotation: tuple[float, ...] | None = None):
        self.joints = tuple(joints)
        self.names = tuple(j.name for j in self.joints)
        self.lower = tuple(float(j.lower) for j in self.joints)
        self.upper = tuple(float(j.upper) for j in self.joints)
        self._links = tuple(_Link.of(j) for j in self.joints)
        self._tool_xyz = tuple(float(c) for c in tool_xyz)
        self._tool_rotation = tuple(tool_rotation) if tool_rotation is not None else _rpy_rotation(tool_rpy)
        self._last_pose: tuple = ((), None)     # (joint positions, their _pose): a warm start begins where a solve ended

    def _pose(self, positions):
        """(tool position, tool rotation, joint origins, joint axes), all in the base frame."""
        positions = tuple(positions)
        if positions == self._last_pose[0]:
            return self._last_pose[1]
        pose = self._compute_pose(positions)
        self._last_pose = (positions, pose)
        return pose

    def _compute_pose(self, positions):
        px = py = pz = 0.0
        r = _IDENTITY
        origins, axes = [], []
        for link, angle in zip(self._links, positions):
            x, y, z = link.xyz
            px += r[0] * x + r[1] * y + r[2] * z
            py += r[3] * x + r[4] * y + r[5] * z
            pz += r[6] * x + r[7] * y + r[8] * z
            if link.rotation is not None:
                r = _multiply(r, link.rotation)
            origins.append((px, py, pz))
            r = _turn(r, link, angle)
            axes.append(_apply(r, link.axis) if link.principal is None else r[link.principal::3])
        x, y, z = _apply(r, self._tool_xyz)
        return (px + x, py + y, pz + z), _multiply(r, self._tool_rotation), origins, axes

    def forward(self, positions) -> "np.ndarray":
        """The tool's 4x4 pose in the base frame."""
        import numpy as np

        position, rotation = self._pose(positions)[:2]
        return np.array([[*rotation[0:3], position[0]], [*rotation[3:6], position[1]],
                         [*rotation[6:9], position[2]], [0.0, 0.0, 0.0, 1.0]])

    def jacobian(self, positions) -> "np.ndarray":
        """6 x n geometric Jacobian of the tool point: rows vx, vy, vz, wx, wy, wz (base frame)."""
        import numpy as np

        tool, _rotation, origins, axes = self._pose(positions)
        return np.array(_jacobian_columns(tool, origins, axes)).T

    def inverse(self, position, orientation, seed, *,
                position_tolerance: float = DEFAULT_POSITION_TOLERANCE,
                orientation_tolerance: float = DEFAULT_ORIENTATION_TOLERANCE,
                max_iterations: int = DEFAULT_MAX_ITERATIONS) -> IKSolution:
        """Joint positions putting the tool at *position* with *orientation* (quaternion), base frame.

        Damped least squares from *seed*, iterated until both tolerances hold;
        starting from the previous tick's solution it takes one or two steps.
        """
        tx, ty, tz = (float(c) for c in position)
        target_rotation = _quaternion_rotation(orientation)
        lower, upper = self.lower, self.upper
        q = [min(max(float(v), low), high) for v, low, high in zip(seed, lower, upper)]
        damping = DAMPING * DAMPING
        for iteration in range(max_iterations + 1):
            tool, rotation, origins, axes = self._pose(q)
            error = (tx - tool[0], ty - tool[1], tz - tool[2]) + _rotation_error(target_rotation, rotation)
            position_norm = math.sqrt(error[0] * error[0] + error[1] * error[1] + error[2] * error[2])
            angle_norm = math.sqrt(error[3] * error[3] + error[4] * error[4] + error[5] * error[5])
            if position_norm <= position_tolerance and angle_norm <= orientation_tolerance:
                return IKSolution(tuple(q), position_norm, angle_norm, iteration, True)
            if iteration == max_iterations:
                break
            # (J^T J + lambda^2 I) step = J^T e: the same step as J^T (J J^T + lambda^2 I)^-1 e
            columns = _jacobian_columns(tool, origins, axes)
            step = _damped_least_squares_step(columns, error, damping)
            largest = max(abs(s) for s in step)
            scale = MAX_JOINT_STEP / largest if largest > MAX_JOINT_STEP else 1.0
            q = [min(max(v + scale * s, low), high) for v, s, low, high in zip(q, step, lower, upper)]
        return IKSolution(tuple(q), position_norm, angle_norm, max_iterations, False)


@dataclass(frozen=True)
class _Link:
    """A joint's constants as plain floats: origin, origin rotation (None: identity), unit axis."""

    xyz: tuple[float, float, float]
    rotation: tuple[float, ...] | None
    axis: tuple[float, float, float]
    principal: int | None          # 0, 1, 2 when the axis is +X, +Y, +Z: a cheaper turn

    @classmethod
    def of(cls, joint: Joint) -> "_Link":
        norm = math.sqrt(sum(c * c for c in joint.axis))
        axis = tuple(float(c) / norm for c in joint.axis)
        principal = axis.index(1.0) if axis in ((1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0)) else None
        if joint.rotation is not None:
            rotation = None if tuple(joint.rotation) == _IDENTITY else tuple(float(c) for c in joint.rotation)
        else:
            rotation = None if tuple(joint.rpy) == (0.0, 0.0, 0.0) else _rpy_rotation(joint.rpy)
        x, y, z = (float(c) for c in joint.xyz)
        ax, ay, az = axis
        return cls((x, y, z), rotation, (ax, ay, az), principal)


_IDENTITY = (1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0)


def _matrix(rotation) -> "np.ndarray":
    import numpy as np

    return np.array(rotation, dtype=float).reshape(3, 3)


def _flat(matrix) -> tuple[float, ...]:
    return tuple(float(matrix[i, j]) for i in range(3) for j in range(3))


def _axis_rotation(axis, angle: float) -> tuple[float, ...]:
    """Rotation about a (not necessarily unit) axis, row-major (Rodrigues)."""
    norm = math.sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2])
    x, y, z = axis[0] / norm, axis[1] / norm, axis[2] / norm
    c, s = math.cos(angle), math.sin(angle)
    t = 1.0 - c
    return (t * x * x + c, t * x * y - s * z, t * x * z + s * y,
            t * x * y + s * z, t * y * y + c, t * y * z - s * x,
            t * x * z - s * y, t * y * z + s * x, t * z * z + c)


def _rpy_rotation(rpy) -> tuple[float, ...]:
    roll, pitch, yaw = (float(c) for c in rpy)
    return _multiply(_multiply(_axis_rotation((0.0, 0.0, 1.0), yaw), _axis_rotation((0.0, 1.0, 0.0), pitch)),
                     _axis_rotation((1.0, 0.0, 0.0), roll))


def _quaternion_rotation(quaternion) -> tuple[float, ...]:
    """The rotation matrix of a quaternion (x, y, z, w; normalised here), row-major."""
    x, y, z, w = (float(c) for c in quaternion)
    return quat_matrix(quat_normalize((x, y, z, w)))


def _multiply(a, b) -> tuple[float, ...]:
    """3x3 product of row-major 9-tuples."""
    a0, a1, a2, a3, a4, a5, a6, a7, a8 = a
    b0, b1, b2, b3, b4, b5, b6, b7, b8 = b
    return (a0 * b0 + a1 * b3 + a2 * b6, a0 * b1 + a1 * b4 + a2 * b7, a0 * b2 + a1 * b5 + a2 * b8,
            a3 * b0 + a4 * b3 + a5 * b6, a3 * b1 + a4 * b4 + a5 * b7, a3 * b2 + a4 * b5 + a5 * b8,
            a6 * b0 + a7 * b3 + a8 * b6, a6 * b1 + a7 * b4 + a8 * b7, a6 * b2 + a7 * b5 + a8 * b8)


def _apply(r, v) -> tuple[float, float, float]:
    return (r[0] * v[0] + r[1] * v[1] + r[2] * v[2], r[3] * v[0] + r[4] * v[1] + r[5] * v[2],
            r[6] * v[0] + r[7] * v[1] + r[8] * v[2])


def _turn(r, link: _Link, angle: float) -> tuple[float, ...]:
    """r @ (rotation about the link's axis by angle); about a principal axis only two columns change."""
    c, s = math.cos(angle), math.sin(angle)
    r0, r1, r2, r3, r4, r5, r6, r7, r8 = r
    if link.principal == 2:
        return (c * r0 + s * r1, c * r1 - s * r0, r2, c * r3 + s * r4, c * r4 - s * r3, r5,
                c * r6 + s * r7, c * r7 - s * r6, r8)
    if link.principal == 1:
        return (c * r0 - s * r2, r1, s * r0 + c * r2, c * r3 - s * r5, r4, s * r3 + c * r5,
                c * r6 - s * r8, r7, s * r6 + c * r8)
    if link.principal == 0:
        return (r0, c * r1 + s * r2, c * r2 - s * r1, r3, c * r4 + s * r5, c * r5 - s * r4,
                r6, c * r7 + s * r8, c * r8 - s * r7)
    return _multiply(r, _axis_rotation(link.axis, angle))


def _jacobian_columns(tool, origins, axes) -> list[tuple[float, ...]]:
    """Per joint: (axis x (tool - joint origin), axis), the tool's linear and angular velocity per unit rate."""
    columns: list[tuple[float, ...]] = []
    for (ox, oy, oz), (ax, ay, az) in zip(origins, axes):
        rx, ry, rz = tool[0] - ox, tool[1] - oy, tool[2] - oz
        columns.append((ay * rz - az * ry, az * rx - ax * rz, ax * ry - ay * rx, ax, ay, az))
    return columns


def _damped_least_squares_step(columns, error, damping: float) -> list[float]:
    """x with (J^T J + damping I) x = J^T e, J's columns given: Cholesky of the normal matrix, built row by row
    as it is factored (the damped normal matrix is symmetric positive definite). Plain floats: numpy's
    per-call overhead exceeds the arithmetic of a 6 x 6 solve."""
    lower: list[list[float]] = []
    for i, a in enumerate(columns):
        a0, a1, a2, a3, a4, a5 = a
        row: list[float] = []
        for j in range(i):
            b, other = columns[j], lower[j]
            total = a0 * b[0] + a1 * b[1] + a2 * b[2] + a3 * b[3] + a4 * b[4] + a5 * b[5]
            for k in range(j):
                total -= row[k] * other[k]
            row.append(total / other[j])
        total = a0 * a0 + a1 * a1 + a2 * a2 + a3 * a3 + a4 * a4 + a5 * a5 + damping
        for k in range(i):
            total -= row[k] * row[k]
        row.append(math.sqrt(total))
        lower.append(row)
    e0, e1, e2, e3, e4, e5 = error
    y: list[float] = []
    for i, (a0, a1, a2, a3, a4, a5) in enumerate(columns):
        total = a0 * e0 + a1 * e1 + a2 * e2 + a3 * e3 + a4 * e4 + a5 * e5
        row = lower[i]
        for k in range(i):
            total -= row[k] * y[k]
        y.append(total / row[i])
    n = len(columns)
    x = [0.0] * n
    for i in reversed(range(n)):
        total = y[i]
        for k in range(i + 1, n):
            total -= lower[k][i] * x[k]
        x[i] = total / lower[i][i]
    return x


def _rotation_error(target, current) -> tuple[float, float, float]:
    """``rotation_error`` on 9-tuples: the rotation vector turning *current* into *target* (world frame)."""
    t0, t1, t2, t3, t4, t5, t6, t7, t8 = target
    c0, c1, c2, c3, c4, c5, c6, c7, c8 = current
    # difference = target @ current.T
    d00, d01, d02 = t0 * c0 + t1 * c1 + t2 * c2, t0 * c3 + t1 * c4 + t2 * c5, t0 * c6 + t1 * c7 + t2 * c8
    d10, d11, d12 = t3 * c0 + t4 * c1 + t5 * c2, t3 * c3 + t4 * c4 + t5 * c5, t3 * c6 + t4 * c7 + t5 * c8
    d20, d21, d22 = t6 * c0 + t7 * c1 + t8 * c2, t6 * c3 + t7 * c4 + t8 * c5, t6 * c6 + t7 * c7 + t8 * c8
    angle = math.acos(min(max((d00 + d11 + d22 - 1.0) / 2.0, -1.0), 1.0))
    vx, vy, vz = d21 - d12, d02 - d20, d10 - d01
    if angle < 1e-9:
        return 0.5 * vx, 0.5 * vy, 0.5 * vz
    if math.pi - angle < 1e-6:  # 180 degrees: the axis is the column of (difference + I) with the largest diagonal
        diagonal = (d00, d11, d22)
        j = diagonal.index(max(diagonal))
        column = ((d00, d10, d20), (d01, d11, d21), (d02, d12, d22))[j]
        column = tuple(c + (1.0 if i == j else 0.0) for i, c in enumerate(column))
        scale = angle / math.sqrt(column[0] * column[0] + column[1] * column[1] + column[2] * column[2])
        return scale * column[0], scale * column[1], scale * column[2]
    scale = angle / (2.0 * math.sin(angle))
    return scale * vx, scale * vy, scale * vz


# UR10 (ros-industrial universal_robot kinetic-devel ur10.urdf.xacro, as graphflow/assets/ur10.usda)
UR10_SUCTION_TIP = 0.1611          # m along ee_link +X (Isaac's legacy SurfaceGripper translate)
UR10_DEFAULT_JOINTS = (-math.pi / 2, -math.pi / 2, -math.pi / 2, -math.pi / 2, math.pi / 2, 0.0)
# ee_link +X (the suction axis) pointing down, as Isaac's euler_angles_to_quat([0, pi/2, 0])
SUCTION_DOWN = (0.0, math.sqrt(0.5), 0.0, math.sqrt(0.5))
_TWO_PI = 2.0 * math.pi


def ur10_chain(tool_offset: float = UR10_SUCTION_TIP) -> SerialChain:
    """The UR10 from base_link to a tool point *tool_offset* along ee_link +X."""
    half_pi = math.pi / 2
    joints = (
        Joint("shoulder_pan_joint", (0.0, 0.0, 0.1273), (0.0, 0.0, 0.0), (0, 0, 1), -_TWO_PI, _TWO_PI),
        Joint("shoulder_lift_joint", (0.0, 0.220941, 0.0), (0.0, half_pi, 0.0), (0, 1, 0), -_TWO_PI, _TWO_PI),
        Joint("elbow_joint", (0.0, -0.1719, 0.612), (0.0, 0.0, 0.0), (0, 1, 0), -math.pi, math.pi),
        Joint("wrist_1_joint", (0.0, 0.0, 0.5723), (0.0, half_pi, 0.0), (0, 1, 0), -_TWO_PI, _TWO_PI),
        Joint("wrist_2_joint", (0.0, 0.1149, 0.0), (0.0, 0.0, 0.0), (0, 0, 1), -_TWO_PI, _TWO_PI),
        Joint("wrist_3_joint", (0.0, 0.0, 0.1157), (0.0, 0.0, 0.0), (0, 1, 0), -_TWO_PI, _TWO_PI),
    )
    # ee_fixed_joint (0, 0.0922, 0) rpy (0, 0, pi/2), then the tool point along ee_link +X
    ee_rotation = _rpy_rotation((0.0, 0.0, half_pi))
    tip = _apply(ee_rotation, (tool_offset, 0.0, 0.0))
    tool_xyz = (tip[0], 0.0922 + tip[1], tip[2])
    return SerialChain(joints, tool_xyz=tool_xyz, tool_rpy=(0.0, 0.0, half_pi))
