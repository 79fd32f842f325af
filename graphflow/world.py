"""The seam between the engine and a physics backend: the one declared backend interface.

The executor only needs a clock that advances one fixed step at a time; nodes,
the surface gripper and the input services need to read and act on prims.
``World`` below declares all of it (and ``Attachments``, the compliant holds a
gripper makes), with the plain data types that cross the seam (``RayHit``,
``Contact``, ``AxisCompliance``), without importing any physics engine.
Implementations: ``graphflow.physics.PyBulletWorld`` (PyBullet, from a USD
stage), ``graphflow.testing.fake_world.FakeWorld`` (kinematic boxes, for tests)
and ``ClockWorld`` below (graphs that name no stage: every physics query raises
``WorldError``).

Tick order (documented in docs/architecture.md): ``world.step()`` advances
physics one step, then the world's attachments (their compliance), then the
world's services (surface-gripper manager, keyboard, gamepad, recorder, ...) in
the order they were added; after that every graph instance ticks once.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from types import MappingProxyType
from typing import (
    Any,
    Callable,
    Hashable,
    Mapping,
    NamedTuple,
    Protocol,
    Sequence,
    TypeVar,
    runtime_checkable,
)

from graphflow.bundles import Bundle
from graphflow.errors import RunFailure
from graphflow.poses import Pose, Vec3

ServiceT = TypeVar("ServiceT")

DEFAULT_TIME_STEP = 1.0 / 60.0   # seconds; Isaac Sim's default physics rate, used when neither graph nor stage sets one


@runtime_checkable
class WorldService(Protocol):
    """Something a world owns: stepped right after every physics step, reset with the world."""

    def after_step(self, dt: float) -> None: ...

    def reset(self) -> None: ...


class Services:
    """The services of one world, one per kind (their class), stepped and reset in the order they were added.

    A world owns exactly one ``Services``; a service is found by its kind
    (``world.services.get(Keyboard)``) or created on first use
    (``world.services.require(Keyboard, make)``), never by attributes set on the
    world from outside or by module-level tables.
    """

    def __init__(self):
        self._by_kind: dict[type, Any] = {}

    def add(self, service: ServiceT, kind: type | None = None) -> ServiceT:
        """Add *service* as the world's one service of *kind* (default: its class), replacing any earlier one."""
        kind = kind or type(service)
        self._by_kind.pop(kind, None)
        self._by_kind[kind] = service
        return service

    def get(self, kind: type[ServiceT]) -> ServiceT | None:
        return self._by_kind.get(kind)

    def require(self, kind: type[ServiceT], make: Callable[[], ServiceT]) -> ServiceT:
        """The service of *kind*, made by ``make()`` and added on first use."""
        service = self._by_kind.get(kind)
        if service is None:
            service = self.add(make(), kind)
        return service

    def __iter__(self):
        return iter(list(self._by_kind.values()))

    def after_step(self, dt: float) -> None:
        for service in list(self._by_kind.values()):
            service.after_step(dt)

    def reset(self) -> None:
        for service in list(self._by_kind.values()):
            service.reset()


class WorldError(RunFailure):
    """A node asked the world for something it cannot do (unknown prim, bad attribute, ...)."""


# -- data that crosses the seam ---------------------------------------------------------------------

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


AXIS_NAMES = ("transX", "transY", "transZ", "rotX", "rotY", "rotZ")


@dataclass(frozen=True)
class AxisCompliance:
    """One D6 axis of an attachment: limits (``lower > upper`` = locked; infinite = free), drive stiffness/damping.

    Translations in m (stiffness N/m), rotations in rad (stiffness N m/rad).
    """

    lower: float = float("-inf")
    upper: float = float("inf")
    stiffness: float = 0.0
    damping: float = 0.0

    @property
    def locked(self) -> bool:
        return self.lower > self.upper

    @property
    def rigid(self) -> bool:
        unbounded = math.isinf(self.lower) and math.isinf(self.upper)
        return self.locked or (unbounded and self.stiffness == 0.0 and self.damping == 0.0)


RIGID = tuple(AxisCompliance(1.0, -1.0) for _ in AXIS_NAMES)     # every axis locked: a rigid hold


# -- the interface ------------------------------------------------------------------------------------

class Attachments(Protocol):
    """A world's compliant attachments (the holds a surface gripper makes), addressed by prim path.

    An attachment holds *target* at its current pose relative to a frame on the
    gripper body (a D6 joint frame, given in the gripper prim's frame), through
    a joint whose six axes comply as ``AxisCompliance`` says (``RIGID``: a
    fixed joint). The gripper body and target stop colliding while held.
    Handles are opaque. The world steps ``update(dt)`` right after each physics
    step (before its services) and ``reset()`` drops every hold.
    """

    def frame(self, gripper_prim: str, frame: Pose) -> Pose | None:
        """World pose of *frame* (given in *gripper_prim*'s frame); None when the prim is no rigid body."""

    def attach(self, gripper_prim: str, frame: Pose, target_prim: str,
               compliance: Sequence[AxisCompliance] = RIGID) -> Hashable | None:
        """Hold *target_prim*; None (nothing held) when either prim is no rigid body."""

    def detach(self, handle: Hashable) -> None:
        """Let go (an unknown or already detached handle is ignored)."""

    def target_of(self, handle: Hashable) -> str:
        """The rigid-body prim a handle holds."""

    def force_on_gripper(self, handle: Hashable, rigid_rows_only: bool = True) -> Vec3:
        """Force the hold puts on the gripper body, world axes, N (Isaac's ``getForce``: force on actor0).

        ``rigid_rows_only``: leave out the part carried by compliant axes inside their limits."""

    def torque_on_gripper(self, handle: Hashable) -> Vec3:
        """Torque the hold puts on the gripper about the attachment frame's origin, world axes, N m."""

    def update(self, dt: float) -> None: ...

    def reset(self) -> None: ...


@runtime_checkable
class World(Protocol):
    """What the executor, nodes, the surface gripper and the input services may use of a world.

    Prim paths in, plain Python values out; SI units; quaternions are (x, y, z, w).
    Anything a world cannot do raises ``WorldError`` naming the prim.
    """

    time_step: float     # seconds per physics step
    time: float          # simulated seconds since the last reset
    step_index: int      # physics steps since the last reset

    services: Services   # owned by the world: stepped after each physics step, reset with it
    stage: Any           # the ``Usd.Stage`` the world was built from, or None
    attachments: Attachments | None       # None: a world without bodies (``ClockWorld``)
    attachment_joints: Mapping[str, Any]   # D6 joints left to the gripper (``graphflow.usd.description.Joint``)

    def step(self) -> None:
        """Advance physics one step, then the attachments, then the services."""

    def reset(self) -> None:
        """Return to the initial state, bit for bit, and reset attachments and services."""

    def window_keys(self):
        """The key source of the world's window (``poll(time) -> [(key, is_down)]``), or None without one."""

    # poses and velocities
    def prim_pose(self, path: str) -> Pose: ...
    def body_poses(self, paths: Sequence[str]) -> list[Pose]:
        """``prim_pose`` of each rigid-body prim, in one query (a recorder samples many bodies every few ticks)."""
    def read_body_poses(self, paths: Sequence[str]) -> Callable[[], list[Pose]]:
        """``body_poses`` read now and returned when called; a world may defer the arithmetic to the call."""
        poses = self.body_poses(paths)
        return lambda: poses
    def prim_velocity(self, path: str) -> tuple[Vec3, Vec3]:
        """(linear m/s, angular rad/s) of the prim's origin, world frame."""

    # joints and drives (DOFs in tree order; rad or m)
    def joint_names(self, articulation_path: str) -> tuple[str, ...]: ...
    def joint_positions(self, articulation_path: str) -> tuple[float, ...]: ...
    def joint_velocities(self, articulation_path: str) -> tuple[float, ...]: ...
    def joint_paths(self, articulation_path: str) -> tuple[str, ...]:
        """The movable joints' prim paths, in DOF order."""
    def joint_efforts(self, articulation_path: str) -> tuple[float, ...]:
        """Effort (N m or N) each DOF's actuation applied during the last step."""
    def joint_dof_types(self, articulation_path: str) -> tuple[int, ...]:
        """Per DOF: 0 rotation (revolute), 1 translation (prismatic)."""
    def set_joint_targets(self, articulation_path: str, indices: Sequence[int], *,
                          positions: Sequence[float] | None = None,
                          velocities: Sequence[float] | None = None,
                          efforts: Sequence[float] | None = None) -> None: ...

    # attributes (USD names and units)
    def get_attribute(self, prim_path: str, name: str): ...
    def set_attribute(self, prim_path: str, name: str, value) -> None: ...
    def read_prim(self, prim_path: str, bounding_box: bool = False, time: float | None = None) -> Bundle:
        """Every attribute of the prim as a bundle (Kit's ReadPrims child): values as composed on the stage
        (at USD time code *time*, None: the default time), the ones the world simulates current, plus
        ``worldMatrix`` (and the bbox attributes when asked)."""

    # queries
    def raycast(self, origin: Vec3, direction: Vec3, length: float) -> RayHit | None: ...
    def raycast_batch(self, origins: Sequence[Vec3], directions: Sequence[Vec3],
                      length: float) -> list[RayHit | None]: ...
    def contacts(self, path: str) -> list[Contact]: ...
    def body_of(self, prim_path: str) -> str | None:
        """The rigid-body prim that simulates *path* (itself, or the body of a collider), None if none."""
    def same_body(self, path_a: str, path_b: str) -> bool:
        """Whether two prims are simulated as one rigid body."""

    # actions
    def apply_force(self, path: str, force: Vec3, position: Vec3 | None = None) -> None:
        """World-frame force (N) at a world point (default: the centre of mass), during the next step only."""
    def gravity_enabled(self, prim_path: str) -> bool: ...
    def set_gravity_enabled(self, prim_path: str, enabled: bool) -> None: ...
    def set_collision_between(self, prim_a: str, prim_b: str, enabled: bool) -> None: ...
    def gravity(self) -> Vec3:
        """The stage's gravity vector, m/s^2."""

    # prims switched off while running (SetPrimActive)
    def prim_active(self, prim_path: str) -> bool:
        """Whether the prim is active: on the stage as authored and not switched off since."""
    def set_prim_active(self, prim_path: str, active: bool) -> None:
        """Take the prim's rigid bodies out of the simulation (False) or back in (True), at rest."""

    # stage edits (stage-21: variant, relationship and material nodes): read the composed stage; edits go to an
    # anonymous layer under the session layer (never a file), are dropped by reset(), and are refused with a
    # WorldError naming the prim when they would change what is simulated (graphflow.usd.stage_edits)
    def variant_sets(self, prim_path: str) -> tuple[str, ...]: ...
    def variant_names(self, prim_path: str, variant_set: str) -> tuple[str, ...]: ...
    def variant_selection(self, prim_path: str, variant_set: str) -> str: ...
    def set_variant_selection(self, prim_path: str, variant_set: str, variant: str) -> None:
        """Select *variant* ('' blocks the selection: the set's fallback or none)."""
    def variant_values(self, prim_path: str, variant_set: str, variant: str) -> Mapping[str, Any]:
        """What the variant authors: ``VariantValue(type_name, value)`` by attribute path."""
    def variant_bindings(self, prim_path: str, variant_set: str, variant: str) -> Mapping[str, tuple[str, ...]]:
        """The material-binding relationships the variant authors: targets by relationship path."""
    def write_stage_values(self, prim_path: str, values: Mapping[str, Any], what: str = "writing values") -> None:
        """Author plain values on attributes (by path) under the prim."""
    def clear_stage_values(self, prim_path: str, attribute_paths: Sequence[str],
                           what: str = "clearing values") -> None: ...
    def relationship_targets(self, prim_path: str, name: str) -> tuple[str, ...]: ...
    def set_relationship_targets(self, prim_path: str, name: str, targets: Sequence[str]) -> None: ...
    def bound_material(self, prim_path: str) -> str:
        """The material bound directly for all purposes, '' when none."""
    def bind_material(self, prim_path: str, material_path: str) -> None: ...

    # animation (MoveTo*, RotateTo*, TranslateTo*, ScaleToSize): prims placed over several ticks
    def local_transform(self, prim_path: str) -> tuple[Vec3, tuple[float, float, float, float], Vec3]:
        """(translation m, orientation (x, y, z, w), scale) of the prim in its parent prim's frame, as now."""
    def set_local_transform(self, prim_path: str, translation: Vec3, orientation: tuple[float, float, float, float],
                            scale: Vec3) -> None:
        """Place the prim in its parent's frame: a free or kinematic body is teleported at rest, another
        Xformable prim gets its xform ops for the run (the files are untouched, a reset undoes it)."""


def on_nearest_ancestor(path: str, query: Callable[[str], ServiceT]) -> tuple[str, ServiceT]:
    """``(prim, query(prim))`` for *path* or, where the world refuses it, its nearest ancestor that it accepts.

    Sensors and publishers name a prim under the body or articulation they read.
    A relative path is refused at once (walking up it would never end); when no
    ancestor is accepted, the world's refusal of *path* itself is raised.
    """
    if not path.startswith("/"):
        raise WorldError(f"{path!r} is not an absolute prim path")
    refusal = None
    candidate = path
    while candidate:
        try:
            return candidate, query(candidate)
        except WorldError as error:
            refusal = refusal or error
        candidate = candidate.rsplit("/", 1)[0]
    raise refusal if refusal is not None else WorldError(f"{path}: no prim")


class ClockWorld:
    """A world with no physics: a fixed-step clock, for graphs that name no stage."""

    def __init__(self, time_step: float = DEFAULT_TIME_STEP):
        if not time_step > 0:
            raise ValueError(f"time step must be positive, got {time_step}")
        self.time_step = time_step
        self.time = 0.0
        self.step_index = 0
        self.services = Services()

    stage = None                                    # no stage,
    attachments: Attachments | None = None          # no bodies to attach,
    attachment_joints: Mapping[str, Any] = MappingProxyType({})    # no attachment joints

    def step(self) -> None:
        self.step_index += 1
        self.time = self.step_index * self.time_step
        self.services.after_step(self.time_step)

    def reset(self) -> None:
        self.time = 0.0
        self.step_index = 0
        self.services.reset()

    def window_keys(self):
        return None

    def _no_physics(self, *_args, **_kwargs):
        raise WorldError("this graph names no stage, so there are no prims to read or write")

    prim_pose = body_poses = read_body_poses = prim_velocity = joint_names = joint_positions = _no_physics
    joint_velocities = _no_physics
    joint_paths = joint_efforts = joint_dof_types = _no_physics
    set_joint_targets = get_attribute = set_attribute = read_prim = gravity = _no_physics
    raycast = raycast_batch = contacts = body_of = same_body = _no_physics
    apply_force = gravity_enabled = set_gravity_enabled = set_collision_between = _no_physics
    prim_active = set_prim_active = _no_physics
    variant_sets = variant_names = variant_selection = set_variant_selection = variant_values = _no_physics
    variant_bindings = write_stage_values = clear_stage_values = _no_physics
    relationship_targets = set_relationship_targets = bound_material = bind_material = _no_physics
    local_transform = set_local_transform = _no_physics
