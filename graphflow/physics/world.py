"""``PyBulletWorld``: graphflow's ``World`` on one PyBullet client, built from a USD stage.

See ``graphflow.physics`` for the public API; this module holds the one class.
"""
from __future__ import annotations

import math
import shutil
import tempfile
from typing import NamedTuple, Sequence

import numpy as np
import pybullet
from pybullet_utils.bullet_client import BulletClient

from graphflow.usd.description import StageDescription
from graphflow.usd.transforms import IDENTITY_POSE, Pose, compose, invert, quat_rotate, relative
from graphflow.world import Services, WorldError

from .contacts import internal_substeps, solver_iterations
from .drive_law import MOTOR_MAX_FORCE, drive_efforts, is_stiff, motor_velocity
from .health import NonFiniteState, first_non_finite, health_plan
from .native_output import native_stdout_silenced
from .builder import ArticulationHandle, BodyHandle, BuiltScene, SceneBuilder

DEFAULT_TIME_STEP = 1.0 / 60.0      # Isaac Sim's default physics rate
SOLVER_ITERATIONS = 50              # PyBullet's default, stated so it stays fixed


class _BoundClient(BulletClient):
    """A ``BulletClient`` that binds each PyBullet function to the client once.

    ``BulletClient.__getattr__`` builds a new ``functools.partial`` on every
    call; the world makes a few dozen calls per step, so the bound function is
    kept on the instance, where later lookups find it without ``__getattr__``.
    """

    def __getattr__(self, name):
        attribute = super().__getattr__(name)
        if name != "disconnect":          # BulletClient forgets its id on disconnect: keep that lookup live
            self.__dict__[name] = attribute
        return attribute


class RayHit(NamedTuple):
    prim_path: str                              # the rigid body (or static collider) that was hit
    position: tuple[float, float, float]
    normal: tuple[float, float, float]
    distance: float


class Contact(NamedTuple):
    other_prim: str | None                      # None: something graphflow does not know (a gripper's helper)
    position: tuple[float, float, float]        # on the other prim, world frame
    normal: tuple[float, float, float]          # from the other prim towards this one
    distance: float                             # negative when penetrating
    normal_force: float


# Attributes nodes may read (R) or write (W); anything else authored on the stage is read-only from USD.
ATTRIBUTES = {
    "drive:linear:physics:targetPosition": "RW prismatic joint drive target, m",
    "drive:angular:physics:targetPosition": "RW revolute joint drive target, degrees (as USD)",
    "drive:linear:physics:targetVelocity": "RW prismatic joint drive target velocity, m/s",
    "drive:angular:physics:targetVelocity": "RW revolute joint drive target velocity, degrees/s",
    "state:linear:physics:position": "R  prismatic joint position, m",
    "state:angular:physics:position": "R  revolute joint position, degrees",
    "state:linear:physics:velocity": "R  prismatic joint velocity, m/s",
    "state:angular:physics:velocity": "R  revolute joint velocity, degrees/s",
    "physics:lowerLimit": "R  joint lower limit (m or degrees, as USD)",
    "physics:upperLimit": "R  joint upper limit (m or degrees, as USD)",
    "xformOp:translate": "RW body position in its parent prim's frame, m (writing teleports the body)",
    "xformOp:orient": "RW body orientation in its parent prim's frame, quaternion (x, y, z, w)",
    "physics:mass": "RW body mass, kg",
    "physics:velocity": "RW body linear velocity in its parent prim's frame, m/s",
    "physics:angularVelocity": "RW body angular velocity in its parent prim's frame, degrees/s (as USD)",
}


class PyBulletWorld:
    """A physics world stepped at a fixed rate; implements ``graphflow.world.World``.

    One PyBullet client per world, so several worlds in one process never
    share state. ``reset()`` rebuilds the client's contents from the parsed
    stage, which reproduces the first run bit for bit.
    """

    def __init__(self, description: StageDescription, stage=None, *, time_step: float | None = None,
                 substeps: int | None = None, gui: bool = False):
        chosen = time_step if time_step is not None else (description.time_step or DEFAULT_TIME_STEP)
        if not chosen > 0:
            raise ValueError(f"time step must be positive, got {chosen}")
        if substeps is None:
            substeps = internal_substeps(chosen)
        if substeps < 1:
            raise ValueError(f"substeps must be at least 1, got {substeps}")
        self.description = description
        self.stage = stage
        self.time_step = float(chosen)
        self.substeps = int(substeps)
        self.solver_iterations = solver_iterations(description.solver_iterations, SOLVER_ITERATIONS)
        self.time = 0.0
        self.step_index = 0
        self.playing = True
        try:
            if gui:
                self.client = _BoundClient(connection_mode=pybullet.GUI)
            else:
                with native_stdout_silenced():
                    self.client = _BoundClient(connection_mode=pybullet.DIRECT)
        except pybullet.error as error:
            raise WorldError(f"cannot open a PyBullet {'GUI' if gui else 'DIRECT'} client: {error}") from None
        self._mesh_directory = tempfile.mkdtemp(prefix="graphflow-meshes-")
        self.services = Services()
        self._closed = False
        self._build()

    # -- construction and timeline ------------------------------------------------------------
    def _build(self):
        client = self.client
        client.resetSimulation()
        client.setPhysicsEngineParameter(fixedTimeStep=self.time_step / self.substeps, numSubSteps=0,
                                         numSolverIterations=self.solver_iterations, deterministicOverlappingPairs=1)
        client.setGravity(*self.description.gravity)
        self.scene: BuiltScene = SceneBuilder(client, self.description, self._mesh_directory).build()
        self._gravity_off = {path for path, handle in self.scene.bodies.items()
                             if not handle.gravity_enabled and handle.kind == "dynamic"}
        self._gravity_plan: list[tuple] | None = None      # from _gravity_off and masses, rebuilt when they change
        self._pending_forces: list[tuple[int, int, tuple, tuple | None]] = []
        self._offsets: dict[str, tuple[str | None, Pose]] = {}
        self._joint_gravity_plans: dict[str, list] = {}      # per articulation: (link, m g) of links with gravity
        self._health_plan = health_plan(self.scene)
        self._limits: dict[str, list[tuple[float, float]]] = {}          # per articulation, by DOF
        self._controlled_articulations: dict[str, bool] = {}

    @property
    def attachment_joints(self):
        """D6 joints excluded from articulation, by joint path (``graphflow.usd.description.Joint``)."""
        return self.description.attachment_joints

    def play(self) -> None:
        self.playing = True

    def pause(self) -> None:
        self.playing = False

    def stop(self) -> None:
        """Like Isaac's stop button: pause and return to the initial state."""
        self.reset()
        self.playing = False

    def reset(self) -> None:
        """Rebuild from the parsed stage (bit-exact initial state), then reset the services."""
        self._build()
        self.time = 0.0
        self.step_index = 0
        self.services.reset()

    def step(self) -> None:
        """One fixed step (``substeps`` PyBullet steps), then the services. No-op while paused."""
        if not self.playing:
            return
        torques = self._drive_torques()      # once per stage step, held over its substeps
        for _ in range(self.substeps):
            self._apply_pre_step_forces(torques)
            self.client.stepSimulation()
        self._pending_forces = []
        broken = first_non_finite(self.client, self._health_plan)
        if broken is not None:
            raise NonFiniteState(f"{broken}: pose or velocity is not finite after physics step {self.step_index + 1} "
                                 f"(t = {(self.step_index + 1) * self.time_step:.4g} s): the simulation diverged")
        self.step_index += 1
        self.time = self.step_index * self.time_step
        self.services.after_step(self.time_step)

    def window_keys(self):
        """The PyBullet window's keys (a DIRECT client reports none)."""
        from .keyboard import PyBulletKeys

        return PyBulletKeys(self.client.getKeyboardEvents)

    def close(self) -> None:
        if not self._closed:
            self._closed = True
            try:
                self.client.disconnect()
            except pybullet.error:
                pass
            shutil.rmtree(self._mesh_directory, ignore_errors=True)

    def __enter__(self) -> "PyBulletWorld":
        return self

    def __exit__(self, *_exc) -> None:
        self.close()

    # -- per-step forces: drives, gravity switches, queued forces -----------------------------------
    def _drive_torques(self) -> list[tuple[ArticulationHandle, list[float]]]:
        """Joint torques of every articulation with drives, efforts, limits or cancelled gravity, this stage step."""
        return [(articulation, self._drive_efforts(articulation, self.time_step))
                for articulation in self.scene.articulations.values()
                if self._controlled(articulation) or any(articulation.efforts)]

    def _controlled(self, articulation: ArticulationHandle) -> bool:
        """Whether an articulation needs joint control every step (drives, limits, gravity cancelled by torques)."""
        controlled = self._controlled_articulations.get(articulation.path)
        if controlled is None:
            controlled = self._controlled_articulations[articulation.path] = (
                any(d is not None for d in articulation.drives)
                or any(math.isfinite(limit) for limits in self._joint_limits(articulation) for limit in limits)
                or any(self.scene.bodies[path].articulation == articulation.path
                       and self._cancelled_by_joint_torques(self.scene.bodies[path]) for path in self._gravity_off))
        return controlled

    def _apply_pre_step_forces(self, torques: list[tuple[ArticulationHandle, list[float]]]):
        client = self.client
        for articulation, forces in torques:
            client.setJointMotorControlArray(articulation.body_id, articulation.joint_indices,
                                             pybullet.TORQUE_CONTROL, forces=forces)
        self._cancel_gravity()
        for body_id, link, force, position in self._pending_forces:
            client.applyExternalForce(body_id, link, force, position, pybullet.WORLD_FRAME)

    def _cancel_gravity(self):
        """Apply -m g at the centre of mass of every dynamic body whose gravity is switched off."""
        if self._gravity_plan is None:
            self._gravity_plan = self._plan_gravity_cancelling()
        client = self.client
        for body_id, base_weight, links, link_weights in self._gravity_plan:
            if base_weight is not None:
                client.applyExternalForce(body_id, -1, base_weight, client.getBasePositionAndOrientation(body_id)[0],
                                          pybullet.WORLD_FRAME)
            if links:   # one forward-kinematics call for all the body's links, not one per link
                states = client.getLinkStates(body_id, links, computeForwardKinematics=1)
                for link, weight, state in zip(links, link_weights, states):
                    client.applyExternalForce(body_id, link, weight, state[0], pybullet.WORLD_FRAME)

    def _plan_gravity_cancelling(self) -> list[tuple]:
        """Per PyBullet body: (id, its base's weight or None, links, their weights) of the bodies in _gravity_off."""
        gravity = self.description.gravity
        plan: dict[int, list] = {}
        for path in sorted(self._gravity_off):
            handle = self.scene.bodies[path]
            if self._cancelled_by_joint_torques(handle):
                continue
            entry = plan.setdefault(handle.body_id, [handle.body_id, None, [], []])
            weight = [-handle.mass * g for g in gravity]
            if handle.link == -1:
                entry[1] = weight
            else:
                entry[2].append(handle.link)
                entry[3].append(weight)
        return [tuple(entry) for entry in plan.values()]

    def _drive_efforts(self, articulation: ArticulationHandle, dt: float) -> list[float]:
        """Joint efforts (PyBullet coordinates) of the drives and feed-forward efforts: ``drive_law``.

        Also sets the joints' velocity motors: those of drives far stiffer than their links, and a
        rigid motor that stops a joint on its limit where this step would carry it past (PyBullet's
        own limits stop a joint only after it passed, and never push it back).
        """
        client = self.client
        states = client.getJointStates(articulation.body_id, articulation.joint_indices)
        signs = articulation.signs
        positions = [sign * s[0] for sign, s in zip(signs, states)]
        velocities = [sign * s[1] for sign, s in zip(signs, states)]
        inertia = self._joint_inertia(articulation, [s[0] for s in states])     # diagonal unchanged by the signs
        diagonal = inertia.diagonal().tolist()
        drives = articulation.drives
        motors = [None if drive is None or not is_stiff(drive, diagonal[dof], dt) else
                  motor_velocity(drive, diagonal[dof], positions[dof], signs[dof] * states[dof][3], dt)
                  for dof, drive in enumerate(drives)]
        load, cancelling = self._joint_gravity(articulation, [s[0] for s in states])
        if all(motor is not None for motor in motors):     # every DOF a motor (the UR10): no torque law to solve
            efforts, accelerations = articulation.efforts, None
        else:
            if -1.0 in signs:   # signs flip rows and columns of M alike, so M in USD coordinates is S M S
                inertia = inertia * np.outer(signs, signs)
            torque_drives = [drive if motor is None else None for drive, motor in zip(drives, motors)]
            efforts, accelerations = drive_efforts(torque_drives, articulation.efforts, positions, velocities,
                                                   inertia, np.array(signs) * load, dt)
            efforts, accelerations = efforts.tolist(), accelerations.tolist()
        targets, forces = [], []
        for dof, (lower, upper) in enumerate(self._joint_limits(articulation)):
            motor = motors[dof]
            velocity = motor if motor is not None else velocities[dof] + dt * accelerations[dof]
            stopped = min(max(velocity, (lower - positions[dof]) / dt), (upper - positions[dof]) / dt)
            if stopped != velocity:
                targets.append(signs[dof] * stopped)
                forces.append(MOTOR_MAX_FORCE)
            elif motor is not None:
                targets.append(signs[dof] * motor)
                forces.append(min(drives[dof].max_force, MOTOR_MAX_FORCE))
            else:
                targets.append(0.0)
                forces.append(0.0)
        client.setJointMotorControlArray(articulation.body_id, articulation.joint_indices,
                                         pybullet.VELOCITY_CONTROL, targetVelocities=targets, forces=forces)
        return [sign * effort + cancel for sign, effort, cancel in zip(signs, efforts, cancelling)]

    def _joint_limits(self, articulation: ArticulationHandle) -> list[tuple[float, float]]:
        """(lower, upper) of each DOF in USD coordinates (infinite where the joint has none)."""
        limits = self._limits.get(articulation.path)
        if limits is None:
            joints = self.description.joints
            limits = self._limits[articulation.path] = [(joints[path].lower, joints[path].upper)
                                                        for path in articulation.joint_paths]
        return limits

    def _cancelled_by_joint_torques(self, handle: BodyHandle) -> bool:
        """A gravity-free link of a fixed-base articulation: its weight is cancelled by joint torques
        (the same generalised force, once per stage step) rather than by a force at its centre of mass
        every substep."""
        return handle.link >= 0 and handle.articulation is not None and \
            self.scene.articulations[handle.articulation].fixed_base

    def _joint_gravity(self, articulation: ArticulationHandle, positions: list[float]) -> tuple[np.ndarray, list]:
        """(gravity load, gravity-cancelling torques) on the DOFs, PyBullet coordinates.

        The load is sum of J^T m g over the links whose gravity is on (the base's weight goes to
        whatever holds the base). On a fixed base, the links whose gravity is off get joint torques
        that cancel their weight: from one inverse-dynamics call, G = -(sum over all links).
        """
        plan = self._joint_gravity_plans.get(articulation.path)
        if plan is None:
            gravity = np.array(self.description.gravity)
            links = [(path, handle.link, handle.mass * gravity) for path, handle in sorted(self.scene.bodies.items())
                     if handle.articulation == articulation.path and handle.link >= 0 and handle.kind == "dynamic"]
            plan = self._joint_gravity_plans[articulation.path] = (
                [(link, weight) for path, link, weight in links if path not in self._gravity_off],
                articulation.fixed_base and any(path in self._gravity_off for path, _link, _weight in links))
        on, cancel_off = plan
        zeros = [0.0] * len(positions)
        load = np.zeros(len(positions))
        offset = 0 if articulation.fixed_base else 6
        for link, weight in on:
            linear, _angular = self.client.calculateJacobian(articulation.body_id, link, (0.0, 0.0, 0.0),
                                                             positions, zeros, zeros)
            load += weight @ np.array(linear)[:, offset:]
        if not cancel_off:
            return load, zeros
        holding_all = self.client.calculateInverseDynamics(articulation.body_id, positions, zeros, zeros)
        return load, [hold + part for hold, part in zip(holding_all, load.tolist())]

    def _joint_inertia(self, articulation: ArticulationHandle, positions: list[float]) -> np.ndarray:
        """The joint-space inertia matrix of the articulation's DOFs (PyBullet coordinates).

        For a floating base, the inertia the joints feel with the base free (the Schur complement):
        the smallest the joints can feel (contacts only add to it), which keeps the drive's load
        estimate from over-correcting (``drive_law``).
        """
        matrix = np.array(self.client.calculateMassMatrix(articulation.body_id, positions))
        if articulation.fixed_base:
            return matrix
        base, joints = matrix[:6, :6], matrix[6:, 6:]
        coupling = matrix[6:, :6]
        return joints - coupling @ np.linalg.solve(base, coupling.T)

    # -- backend-internal API (gripper engineer) ------------------------------------------------
    def body_link(self, prim_path: str) -> tuple[int, int]:
        """(PyBullet body id, link index) of a body prim or of a collider under it."""
        handle = self._body(prim_path)
        return handle.body_id, handle.link

    def inertial_in_prim(self, prim_path: str) -> Pose:
        """The link's inertial (centre-of-mass) frame in the prim frame: PyBullet constraint frames are relative to it."""
        return self._body(prim_path).inertial_in_prim

    def prim_at(self, body_id: int, link_index: int) -> str | None:
        return self.scene.by_id.get((body_id, link_index))

    def set_collision_between(self, prim_a: str, prim_b: str, enabled: bool) -> None:
        a, b = self._body(prim_a), self._body(prim_b)
        self.client.setCollisionFilterPair(a.body_id, b.body_id, a.link, b.link, 1 if enabled else 0)

    def set_gravity_enabled(self, prim_path: str, enabled: bool) -> None:
        handle = self._body(prim_path)
        if enabled:
            self._gravity_off.discard(handle.path)
        elif handle.kind == "dynamic":
            self._gravity_off.add(handle.path)
        self._gravity_plan = None
        self._joint_gravity_plans = {}
        self._controlled_articulations = {}

    # -- lookups ---------------------------------------------------------------------------------
    def _body(self, prim_path: str) -> BodyHandle:
        handle = self.scene.bodies.get(prim_path)
        if handle is not None:
            return handle
        owner = self._collider_owner(prim_path)
        if owner is not None:
            return self.scene.bodies[owner]
        raise WorldError(f"{prim_path} is not a rigid body or collider of this stage")

    def _collider_owner(self, prim_path: str) -> str | None:
        for body in self.description.bodies.values():
            if any(shape.path == prim_path for shape in body.shapes) and body.path in self.scene.bodies:
                return body.path
        return None

    def _articulation(self, path: str) -> ArticulationHandle:
        probe = path
        while probe:
            for articulation in self.scene.articulations.values():
                if probe in articulation.members:
                    return articulation
            owner = self._collider_owner(probe)
            if owner is not None and owner != probe:
                probe = owner
                continue
            probe = probe.rsplit("/", 1)[0]
        raise WorldError(f"{path} is not part of an articulation")

    def _inertial_pose(self, handle: BodyHandle) -> Pose:
        if handle.link == -1:
            position, orientation = self.client.getBasePositionAndOrientation(handle.body_id)
        else:
            state = self.client.getLinkState(handle.body_id, handle.link, computeForwardKinematics=1)
            position, orientation = state[0], state[1]
        return tuple(position), tuple(orientation)

    def _body_pose(self, handle: BodyHandle) -> Pose:
        return compose(self._inertial_pose(handle), invert(handle.inertial_in_prim))

    def _prim_offset(self, prim_path: str) -> tuple[str | None, Pose]:
        """(nearest body ancestor or None, the prim's pose in it), from the stage's authored transforms."""
        if prim_path in self._offsets:
            return self._offsets[prim_path]
        if self.stage is None:
            raise WorldError(f"{prim_path} is not a rigid body of this stage")
        from pxr import Gf, UsdGeom

        prim = self.stage.GetPrimAtPath(prim_path)
        if not prim:
            raise WorldError(f"no prim {prim_path} on this stage")
        transform = Gf.Transform(UsdGeom.XformCache().GetLocalToWorldTransform(prim))
        scale = self.description.meters_per_unit
        imaginary = transform.GetRotation().GetQuat().GetImaginary()
        world = (tuple(float(c) * scale for c in transform.GetTranslation()),
                 (imaginary[0], imaginary[1], imaginary[2], transform.GetRotation().GetQuat().GetReal()))
        ancestor = prim.GetParent()
        while ancestor and not ancestor.IsPseudoRoot() and str(ancestor.GetPath()) not in self.scene.bodies:
            ancestor = ancestor.GetParent()
        owner = str(ancestor.GetPath()) if ancestor and not ancestor.IsPseudoRoot() else None
        offset = relative(self.description.bodies[owner].pose, world) if owner else world
        self._offsets[prim_path] = (owner, offset)
        return owner, offset

    # -- node-facing API ---------------------------------------------------------------------------
    def prim_pose(self, path: str):
        """World pose of a body, a collider, a joint (its body0-side frame) or any Xformable prim."""
        if path in self.scene.bodies:
            return self._body_pose(self.scene.bodies[path])
        joint = self.description.joints.get(path)
        if joint is not None:
            if joint.body0 is None:
                return joint.pose0
            return compose(self.prim_pose(joint.body0), joint.pose0)
        owner = self._collider_owner(path)
        if owner is not None:
            shape = next(s for s in self.description.bodies[owner].shapes if s.path == path)
            return compose(self._body_pose(self.scene.bodies[owner]), shape.pose)
        owner, offset = self._prim_offset(path)
        return compose(self._body_pose(self.scene.bodies[owner]), offset) if owner else offset

    def prim_velocity(self, path: str):
        """(linear, angular) world velocity of the prim's origin; angular in rad/s."""
        handle = self._body(path)
        if handle.link == -1:
            linear, angular = self.client.getBaseVelocity(handle.body_id)
        else:
            state = self.client.getLinkState(handle.body_id, handle.link, computeLinkVelocity=1,
                                             computeForwardKinematics=1)
            linear, angular = state[6], state[7]
        com = self._inertial_pose(handle)[0]
        origin = self.prim_pose(path)[0]
        r = tuple(o - c for o, c in zip(origin, com))
        cross = (angular[1] * r[2] - angular[2] * r[1], angular[2] * r[0] - angular[0] * r[2],
                 angular[0] * r[1] - angular[1] * r[0])
        return tuple(l + c for l, c in zip(linear, cross)), tuple(angular)

    def joint_names(self, articulation_path: str) -> tuple[str, ...]:
        return self._articulation(articulation_path).joint_names

    def joint_paths(self, articulation_path: str) -> tuple[str, ...]:
        return self._articulation(articulation_path).joint_paths

    def joint_positions(self, articulation_path: str) -> tuple[float, ...]:
        articulation = self._articulation(articulation_path)
        if not articulation.joint_indices:
            return ()
        states = self.client.getJointStates(articulation.body_id, articulation.joint_indices)
        return tuple(sign * s[0] for sign, s in zip(articulation.signs, states))

    def joint_velocities(self, articulation_path: str) -> tuple[float, ...]:
        articulation = self._articulation(articulation_path)
        if not articulation.joint_indices:
            return ()
        states = self.client.getJointStates(articulation.body_id, articulation.joint_indices)
        return tuple(sign * s[1] for sign, s in zip(articulation.signs, states))

    def set_joint_targets(self, articulation_path: str, indices: Sequence[int], *,
                          positions: Sequence[float] | None = None, velocities: Sequence[float] | None = None,
                          efforts: Sequence[float] | None = None) -> None:
        """Drive targets by DOF index (rad or m, rad/s or m/s); efforts are added to the drive force."""
        articulation = self._articulation(articulation_path)
        count = len(articulation.joint_paths)
        indices = list(indices)
        for name, values in (("positions", positions), ("velocities", velocities), ("efforts", efforts)):
            if values is not None and len(values) != len(indices):
                raise WorldError(f"{articulation.path}: {len(indices)} joint indices but {len(values)} {name}")
        for slot, index in enumerate(indices):
            if not 0 <= index < count:
                raise WorldError(f"{articulation.path}: joint index {index} out of range (0..{count - 1})")
            drive = articulation.drives[index]
            if (positions is not None or velocities is not None) and drive is None:
                raise WorldError(f"joint {articulation.joint_paths[index]} has no drive to take a target")
            if positions is not None:
                drive.target_position = float(positions[slot])
            if velocities is not None:
                drive.target_velocity = float(velocities[slot])
            if efforts is not None:
                articulation.efforts[index] = float(efforts[slot])

    def apply_force(self, path: str, force, position=None) -> None:
        """Apply a world-frame force (N) at a world point (default: the centre of mass) during the next step."""
        handle = self._body(path)
        point = tuple(position) if position is not None else self._inertial_pose(handle)[0]
        self._pending_forces.append((handle.body_id, handle.link, tuple(float(f) for f in force), point))

    def raycast(self, origin, direction, length: float) -> RayHit | None:
        return self.raycast_batch([origin], [direction], length)[0]

    def raycast_batch(self, origins, directions, length: float) -> list[RayHit | None]:
        """Closest hit of each ray (directions are normalised here), None where nothing is hit."""
        starts, ends = [], []
        for origin, direction in zip(origins, directions):
            norm = math.sqrt(sum(c * c for c in direction))
            if norm == 0.0:
                raise WorldError("a ray needs a non-zero direction")
            starts.append(list(origin))
            ends.append([o + c / norm * length for o, c in zip(origin, direction)])
        hits = []
        for index in range(0, len(starts), pybullet.MAX_RAY_INTERSECTION_BATCH_SIZE):
            hits.extend(self.client.rayTestBatch(starts[index:index + pybullet.MAX_RAY_INTERSECTION_BATCH_SIZE],
                                                 ends[index:index + pybullet.MAX_RAY_INTERSECTION_BATCH_SIZE]))
        result = []
        for body_id, link, fraction, position, normal in hits:
            if body_id < 0:
                result.append(None)
            else:
                result.append(RayHit(self.prim_at(body_id, link) or "", tuple(position), tuple(normal),
                                     fraction * length))
        return result

    def contacts(self, path: str) -> list[Contact]:
        handle = self._body(path)
        points = self.client.getContactPoints(bodyA=handle.body_id, linkIndexA=handle.link)
        return [Contact(self.prim_at(point[2], point[4]), tuple(point[6]), tuple(point[7]), point[8], point[9])
                for point in points]

    # -- attributes ------------------------------------------------------------------------------------
    def _joint_dof(self, prim_path: str, name: str):
        location = self.scene.joint_dofs.get(prim_path)
        if location is None:
            raise WorldError(f"{prim_path} has no attribute {name}: it is not a driven articulation joint")
        articulation = self.scene.articulations[location[0]]
        return articulation, location[1]

    def _unit(self, prim_path: str, name: str) -> float:
        """Scale from SI to the USD value of a joint attribute (degrees for angular joints)."""
        joint = self.description.joints[prim_path]
        angular = joint.kind == "revolute"
        family = "angular" if ":angular:" in name else "linear" if ":linear:" in name else None
        if family is not None and family != ("angular" if angular else "linear"):
            raise WorldError(f"{prim_path} is a {joint.kind} joint: it has no attribute {name}")
        return 180.0 / math.pi if angular else 1.0

    def get_attribute(self, prim_path: str, name: str):
        if name.startswith("drive:") and name.endswith(("targetPosition", "targetVelocity")):
            articulation, dof = self._joint_dof(prim_path, name)
            scale = self._unit(prim_path, name)
            drive = articulation.drives[dof]
            if drive is None:
                raise WorldError(f"{prim_path} has no drive, so no attribute {name}")
            value = drive.target_position if name.endswith("targetPosition") else drive.target_velocity
            return value * scale
        if name.startswith("state:") and name.endswith((":position", ":velocity")):
            articulation, dof = self._joint_dof(prim_path, name)
            scale = self._unit(prim_path, name)
            values = (self.joint_positions if name.endswith(":position") else self.joint_velocities)(articulation.path)
            return values[dof] * scale
        if name in ("physics:lowerLimit", "physics:upperLimit"):
            joint = self.description.joints.get(prim_path)
            if joint is None or joint.kind not in ("revolute", "prismatic"):
                raise WorldError(f"{prim_path} has no attribute {name}: it is not a revolute or prismatic joint")
            value = joint.lower if name == "physics:lowerLimit" else joint.upper
            return value * (180.0 / math.pi if joint.kind == "revolute" else 1.0)
        if name in ("xformOp:translate", "xformOp:orient", "physics:mass", "physics:velocity",
                    "physics:angularVelocity"):
            return self._get_body_attribute(prim_path, name)
        return self._get_usd_attribute(prim_path, name)

    def _parent_rotation(self, prim_path: str):
        parent = prim_path.rsplit("/", 1)[0]
        if not parent:
            return (0.0, 0.0, 0.0, 1.0)
        try:
            return self.prim_pose(parent)[1]
        except WorldError:
            return (0.0, 0.0, 0.0, 1.0)

    def _parent_pose(self, prim_path: str) -> Pose:
        parent = prim_path.rsplit("/", 1)[0]
        if not parent:
            return IDENTITY_POSE
        try:
            return self.prim_pose(parent)
        except WorldError:
            return IDENTITY_POSE

    def _get_body_attribute(self, prim_path: str, name: str):
        handle = self.scene.bodies.get(prim_path)
        if handle is None:
            raise WorldError(f"{prim_path} has no attribute {name}: it is not a rigid body")
        if name == "physics:mass":
            return handle.mass
        if name in ("xformOp:translate", "xformOp:orient"):
            local = relative(self._parent_pose(prim_path), self._body_pose(handle))
            return local[0] if name == "xformOp:translate" else local[1]
        linear, angular = self.prim_velocity(prim_path)
        inverse = invert(((0.0, 0.0, 0.0), self._parent_rotation(prim_path)))[1]
        if name == "physics:velocity":
            return quat_rotate(inverse, linear)
        return tuple(c * 180.0 / math.pi for c in quat_rotate(inverse, angular))

    def _get_usd_attribute(self, prim_path: str, name: str):
        if self.stage is not None:
            prim = self.stage.GetPrimAtPath(prim_path)
            if prim:
                attribute = prim.GetAttribute(name)
                if attribute and attribute.HasValue():
                    return _plain(attribute.Get())
                raise WorldError(f"{prim_path} has no attribute {name}")
        raise WorldError(f"no prim {prim_path} on this stage")

    def set_attribute(self, prim_path: str, name: str, value) -> None:
        if name.startswith("drive:") and name.endswith(("targetPosition", "targetVelocity")):
            articulation, dof = self._joint_dof(prim_path, name)
            scale = self._unit(prim_path, name)
            drive = articulation.drives[dof]
            if drive is None:
                raise WorldError(f"{prim_path} has no drive, so no attribute {name}")
            if name.endswith("targetPosition"):
                drive.target_position = float(value) / scale
            else:
                drive.target_velocity = float(value) / scale
            return
        handle = self.scene.bodies.get(prim_path)
        if name in ("xformOp:translate", "xformOp:orient", "physics:mass", "physics:velocity",
                    "physics:angularVelocity"):
            if handle is None:
                raise WorldError(f"{prim_path} has no writable attribute {name}: it is not a rigid body")
            self._set_body_attribute(handle, name, value)
            return
        if name in ATTRIBUTES:
            raise WorldError(f"{prim_path}: attribute {name} is read-only")
        raise WorldError(f"{prim_path}: attribute {name} cannot be written (writable: "
                         + ", ".join(n for n, doc in ATTRIBUTES.items() if doc.startswith("RW")) + ")")

    def _set_body_attribute(self, handle: BodyHandle, name: str, value):
        client = self.client
        if name == "physics:mass":
            if handle.kind != "dynamic":
                raise WorldError(f"{handle.path}: physics:mass can only be set on a dynamic body")
            mass = float(value)
            if not mass > 0:
                raise WorldError(f"{handle.path}: physics:mass must be positive, got {value}")
            inertia = client.getDynamicsInfo(handle.body_id, handle.link)[2]
            client.changeDynamics(handle.body_id, handle.link, mass=mass,
                                  localInertiaDiagonal=[c * mass / handle.mass for c in inertia])
            handle.mass = mass
            self._gravity_plan = None
            self._joint_gravity_plans = {}
            self._controlled_articulations = {}
            return
        vector = tuple(float(c) for c in value)
        if name in ("xformOp:translate", "xformOp:orient"):
            if handle.link != -1:
                raise WorldError(f"{handle.path}: {name} can only be written on a free body or an articulation root")
            parent = self._parent_pose(handle.path)
            local = relative(parent, self._body_pose(handle))
            local = (vector, local[1]) if name == "xformOp:translate" else (local[0], vector)
            target = compose(compose(parent, local), handle.inertial_in_prim)
            client.resetBasePositionAndOrientation(handle.body_id, target[0], target[1])
            return
        if handle.link != -1:
            raise WorldError(f"{handle.path}: {name} can only be written on a free body or an articulation root")
        rotation = self._parent_rotation(handle.path)
        linear, angular = client.getBaseVelocity(handle.body_id)
        if name == "physics:velocity":
            linear = quat_rotate(rotation, vector)
        else:
            angular = quat_rotate(rotation, tuple(c * math.pi / 180.0 for c in vector))
        client.resetBaseVelocity(handle.body_id, linear, angular)


def _plain(value):
    """USD values as plain Python: Gf vectors and arrays -> tuples, quaternions -> (x, y, z, w)."""
    if hasattr(value, "GetImaginary") and hasattr(value, "GetReal"):
        imaginary = value.GetImaginary()
        return (float(imaginary[0]), float(imaginary[1]), float(imaginary[2]), float(value.GetReal()))
    if isinstance(value, (bool, int, float, str)):
        return value
    if hasattr(value, "__len__") and not isinstance(value, str):
        return tuple(_plain(v) for v in value)
    return str(value) if value is not None else None


__all__ = ["PyBulletWorld", "RayHit", "Contact", "ATTRIBUTES"]
