"""Rigid transforms as plain tuples: positions (x, y, z), quaternions (x, y, z, w).

Core pose math, shared by the USD importer, the physics backends, the gripper
and nodes so all agree on one convention (graphflow's: xyzw, like PyBullet and
OmniGraph attributes; USD's Gf quaternions are (real, i, j, k) and are
converted at the USD boundary).
"""
from __future__ import annotations

import math
from collections.abc import Iterable

Vec3 = tuple[float, float, float]
Quat = tuple[float, float, float, float]
Pose = tuple[Vec3, Quat]

IDENTITY_QUAT: Quat = (0.0, 0.0, 0.0, 1.0)
IDENTITY_POSE: Pose = ((0.0, 0.0, 0.0), IDENTITY_QUAT)
AXIS_VECTORS = {"X": (1.0, 0.0, 0.0), "Y": (0.0, 1.0, 0.0), "Z": (0.0, 0.0, 1.0)}


def as_vec3(values: Iterable[float]) -> Vec3:
    """Three numbers as a typed Vec3 (no conversion: a wrong length raises ValueError)."""
    x, y, z = values
    return (x, y, z)


def quat_multiply(a: Quat, b: Quat) -> Quat:
    ax, ay, az, aw = a
    bx, by, bz, bw = b
    return (aw * bx + ax * bw + ay * bz - az * by,
            aw * by - ax * bz + ay * bw + az * bx,
            aw * bz + ax * by - ay * bx + az * bw,
            aw * bw - ax * bx - ay * by - az * bz)


def quat_conjugate(q: Quat) -> Quat:
    return (-q[0], -q[1], -q[2], q[3])


def quat_normalize(q: Quat) -> Quat:
    x, y, z, w = q
    norm = math.sqrt(x * x + y * y + z * z + w * w)
    if norm == 0.0:
        return IDENTITY_QUAT
    return (x / norm, y / norm, z / norm, w / norm)


def quat_rotate(q: Quat, v: Vec3) -> Vec3:
    x, y, z, w = q
    vx, vy, vz = v
    # t = 2 * cross(q.xyz, v); v' = v + w * t + cross(q.xyz, t)
    tx, ty, tz = 2.0 * (y * vz - z * vy), 2.0 * (z * vx - x * vz), 2.0 * (x * vy - y * vx)
    return (vx + w * tx + (y * tz - z * ty),
            vy + w * ty + (z * tx - x * tz),
            vz + w * tz + (x * ty - y * tx))


def quat_matrix(q: Quat) -> tuple[float, ...]:
    """The rotation matrix of a unit quaternion, row-major 9-tuple: column i is the rotated axis i."""
    x, y, z, w = q
    return (1.0 - 2.0 * (y * y + z * z), 2.0 * (x * y - z * w), 2.0 * (x * z + y * w),
            2.0 * (x * y + z * w), 1.0 - 2.0 * (x * x + z * z), 2.0 * (y * z - x * w),
            2.0 * (x * z - y * w), 2.0 * (y * z + x * w), 1.0 - 2.0 * (x * x + y * y))


def pose_matrix(pose: Pose) -> tuple[float, ...]:
    """A pose as a 4x4 matrix in USD's row-vector layout, flat: row i the rotated axis i, row 3 the position."""
    r = quat_matrix(pose[1])
    x, y, z = pose[0]
    return (r[0], r[3], r[6], 0.0, r[1], r[4], r[7], 0.0, r[2], r[5], r[8], 0.0, x, y, z, 1.0)


def quat_from_axis_angle(axis: Vec3, angle: float) -> Quat:
    half = 0.5 * angle
    s = math.sin(half)
    return (axis[0] * s, axis[1] * s, axis[2] * s, math.cos(half))


def compose(a: Pose, b: Pose) -> Pose:
    """The pose ``a * b``: *b* expressed in the frame *a*."""
    rotated = quat_rotate(a[1], b[0])
    return ((a[0][0] + rotated[0], a[0][1] + rotated[1], a[0][2] + rotated[2]),
            quat_normalize(quat_multiply(a[1], b[1])))


def invert(a: Pose) -> Pose:
    inverse_rotation = quat_conjugate(a[1])
    p = quat_rotate(inverse_rotation, a[0])
    return ((-p[0], -p[1], -p[2]), inverse_rotation)


def relative(a: Pose, b: Pose) -> Pose:
    """*b* expressed in the frame *a*: ``inverse(a) * b``."""
    return compose(invert(a), b)


def twist_angle(q: Quat, axis: Vec3) -> float:
    """The rotation angle of *q* about *axis* (swing-twist decomposition), in radians."""
    projection = q[0] * axis[0] + q[1] * axis[1] + q[2] * axis[2]
    return 2.0 * math.atan2(projection, q[3]) if (projection or q[3]) else 0.0

