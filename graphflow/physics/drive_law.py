"""The joint drive law: PhysX's implicit PD drive, solved with the gravity load the joints carry.

A force drive (stiffness k, damping d) exerts f = k (q* - q - dt v') + d (v* - v') with v' the
joint velocity at the end of the step (backward Euler: stable for any gain). With M the
joint-space inertia and tau the loads on the joints, v' = v + dt a with (M + D) a = r + tau,
D = diag(dt d + dt^2 k), r = k (q* - q - dt v) + d (v* - v), and f = r - D a. At rest a = 0,
so a static load L is held by k e = L: the sag L / k PhysX gives. Leaving tau out (graphflow
before issue 12) held it by k M / (M + D) instead: 6x too soft for a 2 kg load at k = 4e4,
d = 4e3.

tau is the weight of the links beyond each joint, sum of J_i^T m_i g over the articulation's
links whose gravity is on (links with ``physxRigidBody:disableGravity`` carry none), plus the
feed-forward efforts. Loads from contacts, a held object or applied forces are not modelled:
against those a drive is as stiff as k M / (M + D) (a measured load estimate was tried: a joint
blocked by a contact then kept whatever force it had, so a gripper that hit a box stayed down).

A drive far stiffer than its link on a floating base (D > STIFF_RATIO M, the krabby's legs:
D / M ~ 1e5) carries the robot's weight through the ground, which only the contact solver
knows within the step: computed outside it, the legs fold on landing and then kick the robot
into the air. Such drives are PyBullet velocity motors solved with the contacts, aiming at the
velocity the implicit law gives for the force the motor needed last step:
v' = (k (q* - q) + d v* - f_prev) / (dt k + d). At rest v' = 0 where k e = f_prev = L: the sag
is again L / k. (A motor standing for a drive is stable when D > 2 M.) The solver stops iterating at
its residual before a motor quite reaches its target velocity, so at rest the motor holds k e =
f_prev + (dt k + d) delta, delta the velocity it did not reach: 0.215 N m short on a Panda wrist
(19 % of its sag). What it did not reach last step, up to UNREACHED_SPEED, is added to the next
target, which takes delta out of the equilibrium; bounded, it cannot wind up when a contact blocks
the joint.

Acceleration drives are PhysX's per-unit-inertia drives: gains k M_ii and d M_ii. The drive
force is clamped to its max force; feed-forward efforts are added on top.
"""
from __future__ import annotations

import math

import numpy as np

STIFF_RATIO = 4.0          # a floating-base drive with D > STIFF_RATIO M is a velocity motor
MOTOR_MAX_FORCE = 1.0e9    # N or N m: a motor for a drive without a force limit
UNREACHED_SPEED = 2.0e-3   # m/s or rad/s: at most this much of last step's unreached motor velocity is given back


def force_gains(drive, joint_inertia: float) -> tuple[float, float]:
    """(k, d) in force units: an acceleration drive's gains are per unit of the joint's inertia."""
    if drive.acceleration:
        return drive.stiffness * joint_inertia, drive.damping * joint_inertia
    return drive.stiffness, drive.damping


def motor_velocity(drive, target_position: float, target_velocity: float, joint_inertia: float, position: float,
                   last_force: float, dt: float) -> float | None:
    """The velocity a motor standing for a stiff drive aims at, given the force it needed last step; None for a
    drive that is not far stiffer than its link (D = dt d + dt^2 k <= STIFF_RATIO M: the torque law drives it)."""
    k, d = force_gains(drive, joint_inertia)
    implicit = dt * k + d
    if not dt * implicit > STIFF_RATIO * joint_inertia:
        return None
    error = min(max(target_position, drive.lower), drive.upper) - position
    velocity = (k * error + d * target_velocity - last_force) / implicit
    if drive.max_velocity is not None:
        velocity = max(-drive.max_velocity, min(drive.max_velocity, velocity))
    return velocity


def drive_efforts(drives, targets, positions, velocities, inertia: np.ndarray, load: np.ndarray, dt: float,
                  held=None) -> tuple[np.ndarray, np.ndarray]:
    """(joint efforts, predicted joint accelerations) for one step of length *dt*, in USD joint coordinates.

    *drives*: per DOF a ``DriveSpec`` or None (no drive, or a motor drives it); *targets*: the
    articulation's ``DriveTargets`` (target positions and velocities, feed-forward efforts set by
    nodes); *positions*, *velocities*: joint state now; *inertia*: the joint-space inertia matrix;
    *load*: the joints' gravity load; *held*: per DOF the acceleration a motor imposes on it, or None
    for a DOF the torques move. A motor-held joint is not free: left free in the solve, the
    neighbours' loads leak into it (the UR5e's wrist_1 predicted at 71 rad/s^2 while its motor held it).
    """
    count = len(velocities)
    residual = np.zeros(count)
    implicit = np.zeros(count)
    for dof, drive in enumerate(drives):
        if drive is None:
            continue
        k, d = force_gains(drive, inertia[dof, dof])
        velocity = velocities[dof]
        error = min(max(targets.positions[dof], drive.lower), drive.upper) - positions[dof]
        if drive.max_velocity is not None and k > 0 and d > 0:
            limit = drive.max_velocity * (d + dt * k) / k        # where the drive's pull and damping balance at v_max
            error = max(-limit, min(limit, error))
        residual[dof] = k * (error - dt * velocity) + d * (targets.velocities[dof] - velocity)
        implicit[dof] = dt * d + dt * dt * k
    feed_forward = np.asarray(targets.efforts, dtype=float)
    solve = _HeldSolve(inertia, held)
    acceleration = solve(np.diag(implicit), residual + feed_forward + load)
    efforts = residual - implicit * acceleration
    clamped = False
    for dof, drive in enumerate(drives):
        if drive is None:
            efforts[dof] = 0.0
        elif abs(efforts[dof]) > drive.max_force:
            efforts[dof] = math.copysign(drive.max_force, efforts[dof])
            clamped = True
    efforts += feed_forward
    if clamped:     # a saturated drive: the joints accelerate under the forces actually applied
        acceleration = solve(0.0, efforts + load)
    return efforts, acceleration


class _HeldSolve:
    """Solves (M + D) a = f for the free DOFs with the held DOFs' accelerations given: M_ff a_f = f_f - M_fh a_h."""

    def __init__(self, inertia: np.ndarray, held):
        self.inertia = inertia
        if held is None or all(a is None for a in held):
            self.free = None
            return
        self.free = np.array([a is None for a in held])
        self.held = np.array([0.0 if a is None else a for a in held])
        self.coupled = inertia[np.ix_(self.free, ~self.free)] @ self.held[~self.free]

    def __call__(self, implicit, force: np.ndarray) -> np.ndarray:
        matrix = self.inertia + implicit
        if self.free is None:
            return np.linalg.solve(matrix, force)
        acceleration = self.held.copy()
        free = self.free
        acceleration[free] = np.linalg.solve(matrix[np.ix_(free, free)], force[free] - self.coupled)
        return acceleration
