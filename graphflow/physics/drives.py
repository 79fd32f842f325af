"""Joint drives and gravity switches: the forces the world applies before every PyBullet (sub)step.

The drive *definitions* (gains, limits) are the builder's immutable ``DriveSpec``
on each ``ArticulationHandle``; what changes at run time (targets, feed-forward
efforts) is a ``DriveTargets`` per articulation, owned by the world and made
afresh from the parsed stage on every (re)build.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import pybullet

from graphflow.physics.drive_law import MOTOR_MAX_FORCE, UNREACHED_SPEED, drive_efforts, motor_velocity
from graphflow.physics.handles import ArticulationHandle, BodyHandle
from graphflow.poses import quat_conjugate, quat_rotate
from graphflow.usd.description import StageDescription


@dataclass
class DriveTargets:
    """Run-time drive state of one articulation, per DOF (SI units: rad or m, rad/s or m/s, N or N m)."""

    positions: list[float]
    velocities: list[float]
    efforts: list[float]                  # feed-forward efforts set by nodes

    @classmethod
    def authored(cls, articulation: ArticulationHandle, description: StageDescription) -> DriveTargets:
        """The targets the stage authors (0 for undriven DOFs), no efforts."""
        drives = [description.joints[path].drive if spec is not None else None
                  for path, spec in zip(articulation.joint_paths, articulation.drives)]
        return cls([d.target_position if d is not None else 0.0 for d in drives],
                   [d.target_velocity if d is not None else 0.0 for d in drives],
                   [0.0] * len(drives))


class JointControl:
    """What the world applies to the articulations' joints each stage step, held over its substeps.

    Per articulation with drives, limits, efforts or links whose weight joint torques cancel:
    joint torques from the drive law (``drive_law``: the implicit PhysX drive with the links'
    gravity load, feed-forward efforts added), velocity motors for drives far stiffer than their
    links, and a rigid motor that stops a joint on its limit where this step would carry it past
    (PyBullet's own limits stop a joint only after it passed, and never push it back).
    """

    def __init__(self, client, scene, description: StageDescription, gravity: GravitySwitches,
                 targets: dict[str, DriveTargets]):
        self.client = client
        self.scene = scene
        self.gravity = gravity
        self.targets = targets
        joints = description.joints
        self.limits = {path: [(joints[j].lower, joints[j].upper) for j in articulation.joint_paths]
                       for path, articulation in scene.articulations.items()}
        self._plans: dict[str, tuple] = {}        # per articulation: its links' weights, for the switches' version
        self._sent: dict[str, list] = {}          # per articulation: last step's motor velocity targets (USD)
        self._version = -1

    def torques(self, dt: float) -> list[tuple[ArticulationHandle, list[float]]]:
        """(articulation, joint torques in PyBullet coordinates) of every controlled articulation; sets its motors."""
        if self._version != self.gravity.version:
            self._plans.clear()
            self._version = self.gravity.version
        return [(articulation, self._efforts(articulation, self.targets[path], dt))
                for path, articulation in self.scene.articulations.items()
                if self._controlled(articulation) or any(self.targets[path].efforts)]

    def _controlled(self, articulation: ArticulationHandle) -> bool:
        return (articulation.driven
                or any(math.isfinite(limit) for limits in self.limits[articulation.path] for limit in limits)
                or self._gravity_plan(articulation)[1])

    def _efforts(self, articulation: ArticulationHandle, targets: DriveTargets, dt: float) -> list[float]:
        client = self.client
        states = client.getJointStates(articulation.body_id, articulation.joint_indices)
        signs, drives = articulation.signs, articulation.drives
        raw_positions = [s[0] for s in states]
        inertia = joint_inertia(client, articulation, raw_positions)    # diagonal unchanged by the signs
        target_positions, target_velocities = targets.positions, targets.velocities
        positions, velocities, motors = [], [], []
        sent = self._sent.get(articulation.path)
        for dof, (sign, state, drive) in enumerate(zip(signs, states, drives)):
            position = sign * state[0]
            positions.append(position)
            velocities.append(sign * state[1])
            motor = None if drive is None else motor_velocity(drive, target_positions[dof], target_velocities[dof],
                                                              float(inertia[dof][dof]), position, sign * state[3], dt)
            if motor is not None and sent is not None and sent[dof] is not None:
                # what the solver left of last step's target (it stops at SOLVER_RESIDUAL), given back
                unreached = sent[dof] - velocities[dof]
                motor += max(-UNREACHED_SPEED, min(UNREACHED_SPEED, unreached))
            motors.append(motor)
        load, cancelling = self._joint_gravity(articulation, raw_positions)
        if all(motor is not None for motor in motors):     # every DOF a motor (the UR10): no torque law to solve
            efforts, accelerations = targets.efforts, []     # no accelerations needed: every DOF is a motor
        else:
            mass_matrix = np.asarray(inertia)
            if -1.0 in signs:   # signs flip rows and columns of M alike, so M in USD coordinates is S M S
                mass_matrix = mass_matrix * np.outer(signs, signs)
            torque_drives = [drive if motor is None else None for drive, motor in zip(drives, motors)]
            held = [None if motor is None else (motor - velocity) / dt for motor, velocity in zip(motors, velocities)]
            effort_array, acceleration_array = drive_efforts(torque_drives, targets, positions, velocities,
                                                             mass_matrix, np.array(signs) * load, dt, held)
            efforts, accelerations = effort_array.tolist(), acceleration_array.tolist()
        velocity_targets, forces = [], []
        for dof, ((lower, upper), drive) in enumerate(zip(self.limits[articulation.path], drives)):
            motor = motors[dof]
            velocity = motor if motor is not None else velocities[dof] + dt * accelerations[dof]
            stopped = min(max(velocity, (lower - positions[dof]) / dt), (upper - positions[dof]) / dt)
            if stopped != velocity:
                velocity_targets.append(signs[dof] * stopped)
                forces.append(MOTOR_MAX_FORCE)
            elif motor is not None and drive is not None:     # a motor is only made for a drive
                velocity_targets.append(signs[dof] * motor)
                forces.append(min(drive.max_force, MOTOR_MAX_FORCE))
            else:
                velocity_targets.append(0.0)
                forces.append(0.0)
        client.setJointMotorControlArray(articulation.body_id, articulation.joint_indices, pybullet.VELOCITY_CONTROL,
                                         targetVelocities=velocity_targets, forces=forces)
        self._sent[articulation.path] = [None if motor is None else sign * target
                                         for motor, sign, target in zip(motors, signs, velocity_targets)]
        return [sign * effort + cancel for sign, effort, cancel in zip(signs, efforts, cancelling)]

    def _gravity_plan(self, articulation: ArticulationHandle) -> tuple:
        """((link, m g, centre of mass for calculateJacobian) of the links whose gravity is on, whether joint
        torques cancel the weight of the others)."""
        plan = self._plans.get(articulation.path)
        if plan is None:
            gravity = np.array(self.gravity.gravity)
            links = [(path, handle.link, self.gravity.masses[path] * gravity)
                     for path, handle in sorted(self.scene.bodies.items())
                     if handle.articulation == articulation.path and handle.link >= 0 and handle.kind == "dynamic"]
            plan = self._plans[articulation.path] = (
                [(link, weight, self._jacobian_point(articulation.body_id, link))
                 for path, link, weight in links if path not in self.gravity.off],
                articulation.fixed_base and any(path in self.gravity.off for path, _link, _weight in links))
        return plan

    def _jacobian_point(self, body_id: int, link: int) -> tuple:
        """The link's centre of mass as calculateJacobian takes it: measured from the link frame's origin but
        along the inertial frame's axes (found by finite differences of getLinkState; the documented
        "link frame" point missed the UR5e shoulder's load by a third: 10.28 N m for 15.85)."""
        info = self.client.getDynamicsInfo(body_id, link)
        return quat_rotate(quat_conjugate(info[4]), info[3])

    def _joint_gravity(self, articulation: ArticulationHandle, positions: list[float]) -> tuple[np.ndarray, list]:
        """(gravity load, gravity-cancelling torques) on the DOFs, PyBullet coordinates.

        The load is the sum of J^T m g, J at each link's centre of mass, over the links whose gravity is on
        (the base's weight goes to whatever holds the base). On a fixed base, the links whose gravity is off get joint torques
        that cancel their weight: from one inverse-dynamics call, G = -(sum over all links).
        """
        on, cancel_off = self._gravity_plan(articulation)
        zeros = [0.0] * len(positions)
        load = np.zeros(len(positions))
        offset = 0 if articulation.fixed_base else 6
        for link, weight, centre in on:
            linear, _angular = self.client.calculateJacobian(articulation.body_id, link, centre,
                                                             positions, zeros, zeros)
            load += weight @ np.array(linear)[:, offset:]
        if not cancel_off:
            return load, zeros
        holding_all = self.client.calculateInverseDynamics(articulation.body_id, positions, zeros, zeros)
        if not on:        # no link carries its weight: the load is zero (the UR10, whose links all float)
            return load, list(holding_all)
        return load, [hold + part for hold, part in zip(holding_all, load.tolist())]


def joint_inertia(client, articulation: ArticulationHandle, positions: list[float]):
    """The joint-space inertia matrix of the articulation's DOFs (PyBullet coordinates): PyBullet's rows as
    they come for a fixed base (most steps need only the diagonal), a numpy array for a floating base.

    For a floating base, the inertia the joints feel with the base free (the Schur complement):
    the smallest the joints can feel (contacts only add to it), which keeps the drive's load
    estimate from over-correcting (``drive_law``).
    """
    rows = client.calculateMassMatrix(articulation.body_id, positions)
    if articulation.fixed_base:
        return rows
    matrix = np.array(rows)
    base, joints = matrix[:6, :6], matrix[6:, 6:]
    coupling = matrix[6:, :6]
    return joints - coupling @ np.linalg.solve(base, coupling.T)


class GravitySwitches:
    """Bodies whose gravity is off: a counter-force -m g at the centre of mass each (sub)step.

    PyBullet has one gravity per world; this is how a body's ``disableGravity``
    (and the gripper's gravity compensation) is done.
    """

    def __init__(self, bodies: dict[str, BodyHandle], masses: dict[str, float], gravity, by_joint_torques=frozenset()):
        self.bodies = bodies
        self.masses = masses              # the world's live masses (``physics:mass`` can be set)
        self.gravity = gravity
        self.by_joint_torques = by_joint_torques   # links of fixed-base articulations: ``JointControl`` cancels them
        self.off = {path for path, handle in bodies.items() if not handle.gravity_enabled and handle.kind == "dynamic"}
        self.version = 0                  # counts changes of ``off`` and of masses
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
        self.version += 1

    def masses_changed(self) -> None:
        self._plan = None
        self.version += 1

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
        for path in sorted(self.off - self.by_joint_torques):
            if not self.masses[path]:       # a massless body (a fixed base) weighs nothing to cancel
                continue
            handle = self.bodies[path]
            entry = plan.setdefault(handle.body_id, [handle.body_id, None, [], []])
            weight = [-self.masses[path] * g for g in self.gravity]
            if handle.link == -1:
                entry[1] = weight
            else:
                entry[2].append(handle.link)
                entry[3].append(weight)
        return [tuple(entry) for entry in plan.values()]
