"""``PyBulletWorld``: graphflow's ``World`` on one PyBullet client, built from a USD stage.

See ``graphflow.physics`` for the public API. This module holds the world, its
stepping and its node-facing queries; the rest is in cohesive neighbours:
``builder`` (stage description -> PyBullet objects), ``drives`` (drive torques
and gravity switches before each step), ``attributes`` (the attribute table
that dispatches ``get_attribute``/``set_attribute``), ``lookups`` (prim path ->
body, articulation, pose) and ``attachment`` (the gripper's holds).
"""
from __future__ import annotations

import math
import shutil
import tempfile
from typing import Sequence

import pybullet
from pybullet_utils.bullet_client import BulletClient

from graphflow.physics import animation, attributes
from graphflow.physics.activity import PrimActivity
from graphflow.physics.attachment import WorldAttachments
from graphflow.physics.builder import SceneBuilder
from graphflow.physics.contacts import (
    SOLVER_RESIDUAL,
    internal_substeps,
    solver_iterations,
)
from graphflow.physics.drives import DriveTargets, GravitySwitches, JointControl
from graphflow.physics.handles import BuiltScene
from graphflow.physics.health import NonFiniteState, first_non_finite, health_plan
from graphflow.physics.lookups import SceneLookups
from graphflow.physics.native_output import native_stdout_silenced
from graphflow.poses import compose
from graphflow.usd.animation_layer import AnimationLayer
from graphflow.usd.description import StageDescription
from graphflow.usd.errors import warn_unsupported
from graphflow.usd.prim_bundle import PrimReader
from graphflow.usd.stage_edits import StageEditing
from graphflow.world import DEFAULT_TIME_STEP, Contact, RayHit, Services, WorldError

SOLVER_ITERATIONS = 50              # PyBullet's default, stated so it stays fixed
INSIDE_PROBE_RADIUS = 1.0e-4        # m: a ray starts inside a body when this sphere at its origin is 2 radii deep
ATTRIBUTES = attributes.ATTRIBUTES


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


class PyBulletWorld(SceneLookups, StageEditing):
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
        self.solver_residual = SOLVER_RESIDUAL
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
        self.prim_reader = PrimReader()     # what USD composed for each prim read into a bundle, kept for the run
        self.animation_layer = AnimationLayer(stage)    # xform ops the animation nodes write (cleared on reset)
        self.attachments = WorldAttachments(self)
        self.unsupported: list[tuple[str, str]] = list(description.unsupported)
        self._closed = False
        try:
            self._build()
        except BaseException:      # a stage the build refuses: no client or mesh folder left behind
            self.close()
            raise

    # -- construction and timeline ------------------------------------------------------------
    def _build(self):
        """(Re)create everything in the client from the parsed stage, and fresh run-time state."""
        client = self.client
        client.resetSimulation()
        client.setPhysicsEngineParameter(fixedTimeStep=self.time_step / self.substeps, numSubSteps=0,
                                         numSolverIterations=self.solver_iterations, deterministicOverlappingPairs=1,
                                         solverResidualThreshold=self.solver_residual)
        client.setGravity(*self.description.gravity)
        self.scene: BuiltScene = SceneBuilder(client, self.description, self._mesh_directory).build()
        for path, reason in self.scene.unsupported:
            if (path, reason) not in self.unsupported:
                self.unsupported.append((path, reason))
                warn_unsupported(self.description.source, path, reason)
        self.masses = {path: handle.mass for path, handle in self.scene.bodies.items()}
        by_joint_torques = frozenset(path for path, handle in self.scene.bodies.items()
                                     if handle.link >= 0 and handle.articulation is not None
                                     and self.scene.articulations[handle.articulation].fixed_base)
        self.gravity_switches = GravitySwitches(self.scene.bodies, self.masses, self.description.gravity,
                                                by_joint_torques)
        self.drive_targets = {path: DriveTargets.authored(articulation, self.description)
                              for path, articulation in self.scene.articulations.items()}
        self.joint_control = JointControl(client, self.scene, self.description, self.gravity_switches,
                                          self.drive_targets)
        self._health_plan = health_plan(self.scene)
        self._probe: int | None = None          # the collision shape of ``_body_around``
        self._pending_forces: list[tuple[int, int, tuple, tuple | None]] = []
        self._offsets: dict = {}
        self._pose_plans: dict = {}             # body_poses: paths -> which PyBullet calls answer them, last poses
        self._joint_torques: dict[str, list[float]] = {}    # the last step's TORQUE_CONTROL forces, by articulation
        self.activity = PrimActivity(self)                # prims SetPrimActive switched off (all on after a build)

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
        """Rebuild from the parsed stage (bit-exact initial state), then reset attachments and services."""
        self.discard_stage_edits()
        for path in self.animation_layer.clear():
            self.prim_reader.forget(path)
        self._build()
        self.attachments.reset()
        self.time = 0.0
        self.step_index = 0
        self.services.reset()

    def step(self) -> None:
        """One fixed step (``substeps`` PyBullet steps), then attachments and services. No-op while paused."""
        if not self.playing:
            return
        torques = self.joint_control.torques(self.time_step)      # once per stage step, held over its substeps
        self._joint_torques = {articulation.path: forces for articulation, forces in torques}
        for _ in range(self.substeps):
            self._apply_pre_step_forces(torques)
            self.client.stepSimulation()
            self.attachments.after_substep()
        self._pending_forces = []
        broken = first_non_finite(self.client, self._health_plan)
        if broken is not None:
            raise NonFiniteState(f"{broken}: pose or velocity is not finite after physics step {self.step_index + 1} "
                                 f"(t = {(self.step_index + 1) * self.time_step:.4g} s): the simulation diverged")
        self.step_index += 1
        self.time = self.step_index * self.time_step
        self.attachments.update(self.time_step)
        self.services.after_step(self.time_step)

    def window_keys(self):
        """The PyBullet window's keys (a DIRECT client reports none)."""
        from graphflow.physics.keyboard import PyBulletKeys

        return PyBulletKeys(self.client.getKeyboardEvents)

    def close(self) -> None:
        if not self._closed:
            self._closed = True
            self.animation_layer.close()
            try:
                self.client.disconnect()
            except pybullet.error:
                pass
            shutil.rmtree(self._mesh_directory, ignore_errors=True)
            self.discard_stage_edits()      # the stage may outlive the world (a sweep's, the preflight's)

    def __enter__(self) -> "PyBulletWorld":
        return self

    def __exit__(self, *_exc) -> None:
        self.close()

    # -- per-step forces: drives, gravity switches, queued forces -----------------------------------
    def _apply_pre_step_forces(self, torques: list[tuple]):
        client = self.client
        for articulation, forces in torques:
            client.setJointMotorControlArray(articulation.body_id, articulation.joint_indices,
                                             pybullet.TORQUE_CONTROL, forces=forces)
        self.gravity_switches.apply(client)
        for body_id, link, force, position in self._pending_forces:
            client.applyExternalForce(body_id, link, force, position, pybullet.WORLD_FRAME)

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
        return tuple(v + c for v, c in zip(linear, cross)), tuple(angular)

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

    def joint_efforts(self, articulation_path: str) -> tuple[float, ...]:
        """Effort (N m or N) each DOF's actuation applied in the last step: the joint torque the drive law
        set plus what PyBullet's velocity motor applied (``getJointStates``' appliedJointMotorTorque)."""
        articulation = self._articulation(articulation_path)
        if not articulation.joint_indices:
            return ()
        states = self.client.getJointStates(articulation.body_id, articulation.joint_indices)
        torques = self._joint_torques.get(articulation.path) or [0.0] * len(states)
        return tuple(sign * (s[3] + torque) for sign, s, torque in zip(articulation.signs, states, torques))

    def joint_dof_types(self, articulation_path: str) -> tuple[int, ...]:
        """Per DOF: 0 rotation (revolute), 1 translation (prismatic), as Isaac's joint state reports them."""
        return tuple(0 if angular else 1 for angular in self._articulation(articulation_path).angular)

    def set_joint_targets(self, articulation_path: str, indices: Sequence[int], *,
                          positions: Sequence[float] | None = None, velocities: Sequence[float] | None = None,
                          efforts: Sequence[float] | None = None) -> None:
        """Drive targets by DOF index (rad or m, rad/s or m/s); efforts are added to the drive force."""
        articulation = self._articulation(articulation_path)
        targets = self.drive_targets[articulation.path]
        count = len(articulation.joint_paths)
        indices = list(indices)
        for name, values in (("positions", positions), ("velocities", velocities), ("efforts", efforts)):
            if values is not None and len(values) != len(indices):
                raise WorldError(f"{articulation.path}: {len(indices)} joint indices but {len(values)} {name}")
        for slot, index in enumerate(indices):
            if not 0 <= index < count:
                raise WorldError(f"{articulation.path}: joint index {index} out of range (0..{count - 1})")
            if (positions is not None or velocities is not None) and articulation.drives[index] is None:
                raise WorldError(f"joint {articulation.joint_paths[index]} has no drive to take a target")
            if positions is not None:
                targets.positions[index] = float(positions[slot])
            if velocities is not None:
                targets.velocities[index] = float(velocities[slot])
            if efforts is not None:
                targets.efforts[index] = float(efforts[slot])

    def apply_force(self, path: str, force, position=None) -> None:
        """Apply a world-frame force (N) at a world point (default: the centre of mass) during the next step."""
        handle = self._body(path)
        point = tuple(position) if position is not None else self._inertial_pose(handle)[0]
        self._pending_forces.append((handle.body_id, handle.link, tuple(float(f) for f in force), point))

    def raycast(self, origin, direction, length: float) -> RayHit | None:
        """The first hit, PhysX-style: a body the ray starts inside is hit at distance 0."""
        inside = self._body_around(origin)
        if inside is not None:
            return RayHit(inside, tuple(origin), tuple(-c for c in direction), 0.0)
        return self.raycast_batch([origin], [direction], length)[0]

    def _body_around(self, point) -> str | None:
        """The body *point* lies inside, if any (the deepest): PyBullet's rays report only surfaces they
        enter, so a tiny probe sphere is tested against the bodies whose bounding boxes hold the point."""
        client = self.client
        low = [c - INSIDE_PROBE_RADIUS for c in point]
        high = [c + INSIDE_PROBE_RADIUS for c in point]
        candidates = client.getOverlappingObjects(low, high) or ()
        if not candidates:
            return None
        if self._probe is None:     # kept until the world is rebuilt (PyBullet prints a note on removing shapes)
            self._probe = client.createCollisionShape(pybullet.GEOM_SPHERE, radius=INSIDE_PROBE_RADIUS)
        deepest, depth = None, -2.0 * INSIDE_PROBE_RADIUS       # the probe itself overlaps by its diameter
        for body_id, link in candidates:
            for contact in client.getClosestPoints(bodyA=body_id, bodyB=-1, distance=0.0, linkIndexA=link,
                                                   collisionShapeB=self._probe, collisionShapePositionB=list(point)):
                prim = self.prim_at(body_id, link)
                if contact[8] < depth and prim:
                    deepest, depth = prim, contact[8]
        return deepest

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
        result: list[RayHit | None] = []
        for body_id, link, fraction, position, normal in hits:
            if body_id < 0:
                result.append(None)
            else:
                result.append(RayHit(self.prim_at(body_id, link) or "", tuple(position), tuple(normal),
                                     fraction * length))
        return result

    def gravity(self) -> tuple[float, float, float]:
        x, y, z = self.description.gravity
        return float(x), float(y), float(z)

    def contacts(self, path: str) -> list[Contact]:
        handle = self._body(path)
        points = self.client.getContactPoints(bodyA=handle.body_id, linkIndexA=handle.link)
        return [Contact(self.prim_at(point[2], point[4]), tuple(point[6]), tuple(point[7]), point[8], point[9])
                for point in points]

    def get_attribute(self, prim_path: str, name: str):
        """A simulated attribute (see ``ATTRIBUTES``), else the authored USD value (read-only)."""
        return attributes.get_attribute(self, prim_path, name)

    def set_attribute(self, prim_path: str, name: str, value) -> None:
        attributes.set_attribute(self, prim_path, name, value)

    def read_prim(self, prim_path: str, bounding_box: bool = False, time: float | None = None):
        return attributes.read_prim(self, prim_path, bounding_box, time)

    def set_collision_between(self, prim_a: str, prim_b: str, enabled: bool) -> None:
        a, b = self._body(prim_a), self._body(prim_b)
        self.client.setCollisionFilterPair(a.body_id, b.body_id, a.link, b.link, 1 if enabled else 0)

    def gravity_enabled(self, prim_path: str) -> bool:
        """Whether gravity acts on the body (as authored, unless switched since; kinematic: as authored)."""
        return self.gravity_switches.enabled(self._body(prim_path))

    def set_gravity_enabled(self, prim_path: str, enabled: bool) -> None:
        """Switch gravity for one dynamic body (a counter-force -m g at its centre of mass each step)."""
        self.gravity_switches.switch(self._body(prim_path), enabled)

    def prim_active(self, prim_path: str) -> bool:
        return self.activity.is_active(prim_path)

    def set_prim_active(self, prim_path: str, active: bool) -> None:
        """Take the prim's free bodies out of the simulation, or back in (``graphflow.physics.activity``)."""
        self.activity.set_active(prim_path, active)

    # stage edits (stage-21): the methods come from StageEditing; an edit drops what was read from the stage
    def stage_edited(self) -> None:
        self.prim_reader = PrimReader()
        self._offsets = {}

    # -- animation (MoveTo*, RotateTo*, TranslateTo*, ScaleToSize): prims placed over ticks ------------------
    def local_transform(self, prim_path: str):
        return animation.local_transform(self, prim_path)

    def set_local_transform(self, prim_path: str, translation, orientation, scale) -> None:
        animation.set_local_transform(self, prim_path, translation, orientation, scale)


__all__ = ["PyBulletWorld", "RayHit", "Contact", "ATTRIBUTES"]
