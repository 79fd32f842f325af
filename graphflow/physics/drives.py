"""Joint drives and gravity switches: the forces the world applies before every PyBullet (sub)step.

The drive *definitions* (gains, limits) are the builder's immutable ``DriveSpec``
on each ``ArticulationHandle``; what changes at run time (targets, feed-forward
efforts) is a ``DriveTargets`` per articulation, owned by the world and made
afresh from the parsed stage on every (re)build.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pybullet

from graphflow.usd.description import StageDescription

from .builder import ArticulationHandle, BodyHandle

MOTOR_MAX_FORCE = 1.0e9             # N or N m: a floating-base drive without a force limit


@dataclass
class DriveTargets:
    """Run-time drive state of one articulation, per DOF (SI units: rad or m, rad/s or m/s, N or N m)."""

    positions: list[float]
    velocities: list[float]
    efforts: list[float]                  # feed-forward efforts set by nodes

    @classmethod
    def authored(cls, articulation: ArticulationHandle, description: StageDescription) -> "DriveTargets":
        """The targets the stage authors (0 for undriven DOFs), no efforts."""
        drives = [description.joints[path].drive if spec is not None else None
                  for path, spec in zip(articulation.joint_paths, articulation.drives)]
        return cls([d.target_position if d is not None else 0.0 for d in drives],
                   [d.target_velocity if d is not None else 0.0 for d in drives],
                   [0.0] * len(drives))


def apply_drives(client, articulation: ArticulationHandle, targets: DriveTargets, dt: float) -> None:
    """Set this (sub)step's joint motors or torques of one articulation."""
    if not articulation.fixed_base:
        drive_floating(client, articulation, targets, dt)
    elif articulation.driven or any(targets.efforts):
        client.setJointMotorControlArray(articulation.body_id, articulation.joint_indices, pybullet.TORQUE_CONTROL,
                                         forces=drive_efforts(client, articulation, targets, dt))


def drive_efforts(client, articulation: ArticulationHandle, targets: DriveTargets, dt: float) -> list[float]:
    """Joint efforts of the drives: a PD law integrated implicitly (backward Euler).

    A force drive's effort is f = k (q* - q - dt v') + d (v* - v'), with v' the
    velocity at the end of the step. With M the joint-space inertia matrix and
    D = diag(dt d + dt^2 k) this gives (M + D) a = r, r = k (q* - q - dt v) +
    d (v* - v), and f = M a: stable for any gain at 60 Hz, where an explicit
    spring (or one using only M's diagonal) blows up on a stiff, coupled arm.
    Acceleration drives (PhysX semantics: gains per unit of inertia) use the
    joint's own inertia M_ii: f = M_ii r / (1 + dt d + dt^2 k). Feed-forward
    efforts are added, then each result is clamped to the drive's max force.
    Targets beyond the joint's limits are pursued only up to the limit, so a
    stiff drive does not push the joint through PyBullet's (soft) limit.
    A joint's max velocity limits the position error the spring sees to
    v_max (d + dt k) / k, where the drive's pull and damping balance at v_max (PyBullet's
    own velocity clamp fights an implicit drive, so it is not used).
    """
    states = client.getJointStates(articulation.body_id, articulation.joint_indices)
    signs = articulation.signs
    count = len(states)
    inertia = joint_inertia(client, articulation, [s[0] for s in states])
    efforts = list(targets.efforts)
    target_positions, target_velocities = targets.positions, targets.velocities
    residual = [0.0] * count
    implicit = [0.0] * count
    force_driven = []
    for dof, drive in enumerate(articulation.drives):
        if drive is None:
            continue
        k, d = drive.stiffness, drive.damping
        sign, state = signs[dof], states[dof]
        position, velocity = sign * state[0], sign * state[1]
        error = min(max(target_positions[dof], drive.lower), drive.upper) - position
        if drive.max_velocity is not None and k > 0 and d > 0:
            limit = drive.max_velocity * (d + dt * k) / k
            error = max(-limit, min(limit, error))
        r = k * (error - dt * velocity) + d * (target_velocities[dof] - velocity)
        if drive.acceleration:
            efforts[dof] += float(inertia[dof, dof]) * r / (1.0 + dt * d + dt * dt * k)
        else:
            residual[dof] = r
            implicit[dof] = dt * d + dt * dt * k
            force_driven.append(dof)
    if force_driven:
        if -1.0 in signs:   # signs flip rows and columns of M alike, so M in USD coordinates is S M S
            inertia = inertia * np.outer(signs, signs)
        matrix = inertia + np.diag(implicit)
        acceleration = np.linalg.solve(matrix, residual).tolist()
        for dof in force_driven:
            efforts[dof] += residual[dof] - implicit[dof] * acceleration[dof]
    result = []
    for dof, drive in enumerate(articulation.drives):
        effort = efforts[dof]
        if drive is not None:
            effort = max(-drive.max_force, min(drive.max_force, effort))
        result.append(signs[dof] * effort)
    return result


def drive_floating(client, articulation: ArticulationHandle, targets: DriveTargets, dt: float) -> None:
    """Drives of a floating-base articulation: PyBullet joint motors, solved with the contacts.

    A legged robot stands on its drives: the load on a leg is the ground's reaction, which
    only the constraint solver knows, in the same step. The torque drive of
    ``drive_efforts`` cannot include it: it holds a static load L with k M / (M + D)
    instead of k, and for light legs under stiff gains (the krabby: M ~ 0.1 kg m^2,
    D ~ 6e4) the legs folded by 0.35 rad. Here each drive is PhysX's implicit drive
    f = k (q* - q - dt v') + d (v* - v') taken in its stiff limit: a velocity motor with
    target v' = (k (q* - q) + d v*) / (dt k + d) (the velocity at which f = 0; max velocity
    clamps it) and the drive's max force, solved with the contacts. Both drive types have
    this target. It is exact as long as the drive is stiff for the link (dt (dt k + d) >> M,
    i.e. D >> M); a soft drive is then rigid against loads, where PhysX would give way by L / k.
    Feed-forward efforts are added as joint torques.
    """
    signs = articulation.signs
    states = client.getJointStates(articulation.body_id, articulation.joint_indices)
    indices, velocities, forces = [], [], []
    for dof, drive in enumerate(articulation.drives):
        if drive is None:
            continue
        k, d = drive.stiffness, drive.damping
        if not dt * k + d > 0.0:
            continue
        error = min(max(targets.positions[dof], drive.lower), drive.upper) - signs[dof] * states[dof][0]
        velocity = (k * error + d * targets.velocities[dof]) / (dt * k + d)
        if drive.max_velocity is not None:
            velocity = max(-drive.max_velocity, min(drive.max_velocity, velocity))
        indices.append(articulation.joint_indices[dof])
        velocities.append(signs[dof] * velocity)
        forces.append(min(drive.max_force, MOTOR_MAX_FORCE))
    if indices:
        client.setJointMotorControlArray(articulation.body_id, indices, pybullet.VELOCITY_CONTROL,
                                         targetVelocities=velocities, forces=forces)
    if any(targets.efforts):
        client.setJointMotorControlArray(articulation.body_id, articulation.joint_indices, pybullet.TORQUE_CONTROL,
                                         forces=[sign * effort for sign, effort in zip(signs, targets.efforts)])


def joint_inertia(client, articulation: ArticulationHandle, positions: list[float]) -> np.ndarray:
    """The joint-space inertia matrix of the articulation's DOFs (PyBullet coordinates)."""
    matrix = np.array(client.calculateMassMatrix(articulation.body_id, positions))
    offset = 0 if articulation.fixed_base else 6
    return matrix[offset:offset + len(positions), offset:offset + len(positions)]


class GravitySwitches:
    """Bodies whose gravity is off: a counter-force -m g at the centre of mass each (sub)step.

    PyBullet has one gravity per world; this is how a body's ``disableGravity``
    (and the gripper's gravity compensation) is done.
    """

    def __init__(self, bodies: dict[str, BodyHandle], masses: dict[str, float], gravity):
        self.bodies = bodies
        self.masses = masses              # the world's live masses (``physics:mass`` can be set)
        self.gravity = gravity
        self.off = {path for path, handle in bodies.items() if not handle.gravity_enabled and handle.kind == "dynamic"}
        self._plan: list[tuple] | None = None      # from ``off`` and masses, rebuilt when they change

    def enabled(self, handle: BodyHandle) -> bool:
        """Whether gravity acts on the body (as authored, unless switched since; kinematic: as authored)."""
        return handle.path not in self.off if handle.kind == "dynamic" else handle.gravity_enabled

    def switch(self, handle: BodyHandle, enabled: bool) -> None:
        if enabled:
            self.off.discard(handle.path)
        elif handle.kind == "dynamic":
            self.off.add(handle.path)
        self._plan = None

    def masses_changed(self) -> None:
        self._plan = None

    def apply(self, client) -> None:
        """Apply -m g at the centre of mass of every dynamic body whose gravity is switched off."""
        if self._plan is None:
            self._plan = self._make_plan()
        for body_id, base_weight, links, link_weights in self._plan:
            if base_weight is not None:
                client.applyExternalForce(body_id, -1, base_weight, client.getBasePositionAndOrientation(body_id)[0],
                                          pybullet.WORLD_FRAME)
            if links:   # one forward-kinematics call for all the body's links, not one per link
                states = client.getLinkStates(body_id, links, computeForwardKinematics=1)
                for link, weight, state in zip(links, link_weights, states):
                    client.applyExternalForce(body_id, link, weight, state[0], pybullet.WORLD_FRAME)

    def _make_plan(self) -> list[tuple]:
        """Per PyBullet body: (id, its base's weight or None, links, their weights) of the bodies switched off."""
        plan: dict[int, list] = {}
        for path in sorted(self.off):
            handle = self.bodies[path]
            entry = plan.setdefault(handle.body_id, [handle.body_id, None, [], []])
            weight = [-self.masses[path] * g for g in self.gravity]
            if handle.link == -1:
                entry[1] = weight
            else:
                entry[2].append(handle.link)
                entry[3].append(weight)
        return [tuple(entry) for entry in plan.values()]
