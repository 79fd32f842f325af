"""Serial-arm kinematics in numpy: forward kinematics, Jacobian, damped-least-squares IK.

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
from typing import Sequence

import numpy as np

DEFAULT_POSITION_TOLERANCE = 1e-5     # m: 100x below the 1 mm the controllers need
DEFAULT_ORIENTATION_TOLERANCE = 1e-4  # rad
DEFAULT_MAX_ITERATIONS = 200
DAMPING = 0.02                        # damped least squares: lambda (m, rad), keeps steps finite near singularities
MAX_JOINT_STEP = 0.3                  # rad per iteration: Newton steps far from the solution can overshoot


def rotation_from_rpy(roll: float, pitch: float, yaw: float) -> np.ndarray:
    """URDF's fixed-axis roll-pitch-yaw: R = Rz(yaw) Ry(pitch) Rx(roll)."""
    return _rotation_about((0, 0, 1), yaw) @ _rotation_about((0, 1, 0), pitch) @ _rotation_about((1, 0, 0), roll)


def _rotation_about(axis, angle: float) -> np.ndarray:
    x, y, z = np.asarray(axis, dtype=float) / np.linalg.norm(axis)
    c, s = math.cos(angle), math.sin(angle)
    t = 1.0 - c
    return np.array([[t * x * x + c, t * x * y - s * z, t * x * z + s * y],
                     [t * x * y + s * z, t * y * y + c, t * y * z - s * x],
                     [t * x * z - s * y, t * y * z + s * x, t * z * z + c]])


def quaternion_to_matrix(quaternion: Sequence[float]) -> np.ndarray:
    x, y, z, w = np.asarray(quaternion, dtype=float) / np.linalg.norm(quaternion)
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
                     [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
                     [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]])


def matrix_to_quaternion(matrix: np.ndarray) -> tuple[float, float, float, float]:
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


def rotation_error(target: np.ndarray, current: np.ndarray) -> np.ndarray:
    """The rotation vector (axis * angle, world frame) that turns *current* into *target*."""
    difference = target @ current.T
    cos_angle = np.clip((np.trace(difference) - 1.0) / 2.0, -1.0, 1.0)
    angle = math.acos(cos_angle)
    vector = np.array([difference[2, 1] - difference[1, 2], difference[0, 2] - difference[2, 0],
                       difference[1, 0] - difference[0, 1]])
    if angle < 1e-9:
        return 0.5 * vector
    if math.pi - angle < 1e-6:  # 180 degrees: the axis is the column of (R + I) with the largest norm
        column = (difference + np.eye(3))[:, int(np.argmax(np.diag(difference)))]
        return angle * column / np.linalg.norm(column)
    return angle * vector / (2.0 * math.sin(angle))


@dataclass(frozen=True)
class Joint:
    name: str
    xyz: tuple[float, float, float]
    rpy: tuple[float, float, float]
    axis: tuple[float, float, float]
    lower: float
    upper: float


@dataclass(frozen=True)
class IKSolution:
    positions: tuple[float, ...]
    position_error: float        # m, at the tool point
    orientation_error: float     # rad
    iterations: int
    converged: bool


class SerialChain:
    """A fixed-base chain of revolute joints ending in a tool frame (all in the base frame)."""

    def __init__(self, joints: Sequence[Joint], tool_xyz=(0.0, 0.0, 0.0), tool_rpy=(0.0, 0.0, 0.0)):
        self.joints = tuple(joints)
        self.names = tuple(j.name for j in self.joints)
        self.lower = np.array([j.lower for j in self.joints])
        self.upper = np.array([j.upper for j in self.joints])
        self._origins = [_transform(j.xyz, j.rpy) for j in self.joints]
        self._axes = [np.asarray(j.axis, dtype=float) / np.linalg.norm(j.axis) for j in self.joints]
        self._tool = _transform(tool_xyz, tool_rpy)

    def _frames(self, positions) -> tuple[list[np.ndarray], np.ndarray]:
        frames, current = [], np.eye(4)
        for origin, axis, angle in zip(self._origins, self._axes, positions):
            current = current @ origin
            frames.append(current)
            rotation = np.eye(4)
            rotation[:3, :3] = _rotation_about(axis, angle)
            current = current @ rotation
        return frames, current @ self._tool

    def forward(self, positions) -> np.ndarray:
        """The tool's 4x4 pose in the base frame."""
        return self._frames(positions)[1]

    def jacobian(self, positions) -> np.ndarray:
        """6 x n geometric Jacobian of the tool point: rows vx, vy, vz, wx, wy, wz (base frame)."""
        frames, tool = self._frames(positions)
        columns = []
        for frame, axis in zip(frames, self._axes):
            z = frame[:3, :3] @ axis
            columns.append(np.concatenate([np.cross(z, tool[:3, 3] - frame[:3, 3]), z]))
        return np.array(columns).T

    def inverse(self, position, orientation, seed, *,
                position_tolerance: float = DEFAULT_POSITION_TOLERANCE,
                orientation_tolerance: float = DEFAULT_ORIENTATION_TOLERANCE,
                max_iterations: int = DEFAULT_MAX_ITERATIONS) -> IKSolution:
        """Joint positions putting the tool at *position* with *orientation* (quaternion), base frame.

        Damped least squares from *seed*, iterated until both tolerances hold;
        starting from the previous tick's solution it takes one or two steps.
        """
        target_position = np.asarray(position, dtype=float)
        target_rotation = quaternion_to_matrix(orientation)
        q = np.clip(np.asarray(seed, dtype=float), self.lower, self.upper)
        damping = DAMPING * DAMPING * np.eye(6)
        for iteration in range(max_iterations + 1):
            tool = self.forward(q)
            position_error = target_position - tool[:3, 3]
            angle_error = rotation_error(target_rotation, tool[:3, :3])
            position_norm, angle_norm = float(np.linalg.norm(position_error)), float(np.linalg.norm(angle_error))
            if position_norm <= position_tolerance and angle_norm <= orientation_tolerance:
                return IKSolution(tuple(float(v) for v in q), position_norm, angle_norm, iteration, True)
            if iteration == max_iterations:
                break
            j = self.jacobian(q)
            step = j.T @ np.linalg.solve(j @ j.T + damping, np.concatenate([position_error, angle_error]))
            largest = float(np.max(np.abs(step)))
            if largest > MAX_JOINT_STEP:
                step *= MAX_JOINT_STEP / largest
            q = np.clip(q + step, self.lower, self.upper)
        return IKSolution(tuple(float(v) for v in q), position_norm, angle_norm, max_iterations, False)


def _transform(xyz, rpy) -> np.ndarray:
    matrix = np.eye(4)
    matrix[:3, :3] = rotation_from_rpy(*rpy)
    matrix[:3, 3] = xyz
    return matrix


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
    ee_link = _transform((0.0, 0.0922, 0.0), (0.0, 0.0, half_pi)) @ _transform((tool_offset, 0.0, 0.0), (0, 0, 0))
    return SerialChain(joints, tool_xyz=tuple(ee_link[:3, 3]), tool_rpy=(0.0, 0.0, half_pi))
