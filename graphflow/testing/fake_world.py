"""A second backend: ``FakeWorld``, the world interface on kinematic boxes, no physics engine.

For tests of what sits on top of ``graphflow.world.World`` (the surface gripper,
nodes, services) without PyBullet: bodies are axis-aligned boxes that stay
where they are put (``add_box``, ``move``), rays hit the nearest box face,
articulations reach their joint targets at once, attributes are a table, and
attachments record what is held and report the forces and torques a test sets
(``FakeAttachments.forces``). Every ray cast is kept in ``world.rays`` and
every applied force in ``world.applied_forces`` (for the step it acts on).

A ray starting inside a box hits it at distance 0, so a gripper's rays that
start inside its own body see it (as Isaac's self-hit loop expects).
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Hashable, Mapping, Sequence

from graphflow.bundles import Bundle, BundleAttribute, type_of_value
from graphflow.poses import IDENTITY_QUAT, Pose, Vec3, as_vec3, compose, pose_matrix
from graphflow.usd.stage_edits import StageEditing
from graphflow.world import (
    DEFAULT_TIME_STEP,
    RIGID,
    AxisCompliance,
    Contact,
    RayHit,
    Services,
    WorldError,
)

ZERO: Vec3 = (0.0, 0.0, 0.0)


@dataclass
class Box:
    """A kinematic body: an axis-aligned box (centre, half extents) with an orientation for its frame."""

    path: str
    center: Vec3
    half_extents: Vec3
    orientation: tuple[float, float, float, float] = IDENTITY_QUAT
    gravity: bool = True

    def contains(self, point: Vec3) -> bool:
        return all(abs(point[i] - self.center[i]) <= self.half_extents[i] for i in range(3))


@dataclass
class _Hold:
    gripper: str
    frame: Pose
    target: str
    compliance: tuple[AxisCompliance, ...]


class FakeAttachments:
    """``graphflow.world.Attachments`` that records holds and reports the forces a test sets.

    ``forces[target]`` / ``torques[target]``: what every hold on *target* reports
    on the gripper (default zero); ``force_on_gripper(handle, False)`` reports
    ``whole_forces[target]`` if set, else the same force.
    """

    def __init__(self, world: "FakeWorld"):
        self.world = world
        self.holds: dict[Hashable, _Hold] = {}
        self.forces: dict[str, Vec3] = {}
        self.whole_forces: dict[str, Vec3] = {}
        self.torques: dict[str, Vec3] = {}
        self.updates = 0
        self._next = 0

    def frame(self, gripper_prim: str, frame: Pose) -> Pose | None:
        if self.world.body_of(gripper_prim) is None:
            return None
        return compose(self.world.prim_pose(gripper_prim), frame)

    def attach(self, gripper_prim: str, frame: Pose, target_prim: str,
               compliance: Sequence[AxisCompliance] = RIGID) -> int | None:
        gripper, target = self.world.body_of(gripper_prim), self.world.body_of(target_prim)
        if gripper is None or target is None:
            return None
        self._next += 1
        self.holds[self._next] = _Hold(gripper, frame, target, tuple(compliance))
        return self._next

    def detach(self, handle: Hashable) -> None:
        self.holds.pop(handle, None)

    def target_of(self, handle: Hashable) -> str:
        return self.holds[handle].target

    def held(self) -> list[str]:
        """The held bodies, one entry per hold, in attach order."""
        return [hold.target for hold in self.holds.values()]

    def force_on_gripper(self, handle: Hashable, rigid_rows_only: bool = True) -> Vec3:
        target = self.holds[handle].target
        if not rigid_rows_only and target in self.whole_forces:
            return self.whole_forces[target]
        return self.forces.get(target, ZERO)

    def torque_on_gripper(self, handle: Hashable) -> Vec3:
        return self.torques.get(self.holds[handle].target, ZERO)

    def update(self, dt: float) -> None:
        self.updates += 1

    def reset(self) -> None:
        self.holds.clear()
        self.updates = 0


class FakeWorld(StageEditing):
    """``graphflow.world.World`` without a physics engine (see the module docstring)."""

    def __init__(self, time_step: float = DEFAULT_TIME_STEP, *, stage=None,
                 attachment_joints: Mapping[str, Any] | None = None):
        if not time_step > 0:
            raise ValueError(f"time step must be positive, got {time_step}")
        self.time_step = time_step
        self.time = 0.0
        self.step_index = 0
        self.stage = stage
        self.attachment_joints = dict(attachment_joints or {})
        self.services = Services()
        self.attachments = FakeAttachments(self)
        self.boxes: dict[str, Box] = {}
        self.frames: dict[str, tuple[str, Pose]] = {}       # prim on a box -> (box, pose in the box frame)
        self.articulations: dict[str, dict] = {}
        self.attributes: dict[tuple[str, str], Any] = {}
        self.rays: list[tuple[Vec3, Vec3, float]] = []
        self.applied_forces: list[tuple[str, Vec3, Vec3 | None]] = []
        self.no_collision: set[frozenset[str]] = set()
        self.inactive: set[str] = set()                     # prims SetPrimActive switched off (the boxes stay)
        self.scales: dict[str, Vec3] = {}                   # box -> scale an animation set (local_transform)
        self._pending_forces: list[tuple[str, Vec3, Vec3 | None]] = []

    # -- building the scene --

    def add_box(self, path: str, center: Vec3, half_extents: Vec3, *,
                orientation=IDENTITY_QUAT, gravity: bool = True) -> Box:
        box = self.boxes[path] = Box(path, as_vec3(center), as_vec3(half_extents), tuple(orientation), gravity)
        return box

    def add_frame(self, path: str, body: str, pose: Pose) -> None:
        """A prim carried by a box (a joint, a sensor...): *pose* in the box's frame."""
        self._box(body)
        self.frames[path] = (body, pose)

    def move(self, path: str, center: Vec3) -> None:
        self._box(path).center = as_vec3(center)

    def remove(self, path: str) -> None:
        self.boxes.pop(path, None)

    def add_articulation(self, path: str, joint_names: Sequence[str]) -> None:
        """Joints that reach their position targets at once (velocities stay 0)."""
        self.articulations[path] = {"names": tuple(joint_names), "positions": [0.0] * len(joint_names),
                                    "efforts": [0.0] * len(joint_names)}

    # -- timeline --

    def step(self) -> None:
        self.applied_forces = self._pending_forces
        self._pending_forces = []
        self.step_index += 1
        self.time = self.step_index * self.time_step
        self.attachments.update(self.time_step)
        self.services.after_step(self.time_step)

    def reset(self) -> None:
        self.time = 0.0
        self.step_index = 0
        self._pending_forces = []
        self.applied_forces = []
        self.inactive.clear()
        self.discard_stage_edits()      # stage edits (stage-21): StageEditing's methods, on self.stage
        self.attachments.reset()
        self.services.reset()

    def window_keys(self):
        return None

    # -- lookups --

    def _box(self, path: str) -> Box:
        box = self.boxes.get(path)
        if box is None:
            raise WorldError(f"{path} is not a body of this fake world")
        return box

    def body_of(self, prim_path: str) -> str | None:
        if prim_path in self.boxes:
            return prim_path
        carried = self.frames.get(prim_path)
        return carried[0] if carried is not None and carried[0] in self.boxes else None

    def same_body(self, path_a: str, path_b: str) -> bool:
        if path_a == path_b:
            return True
        body = self.body_of(path_a)
        return body is not None and body == self.body_of(path_b)

    # -- poses --

    def prim_pose(self, path: str) -> Pose:
        if path in self.boxes:
            box = self.boxes[path]
            return box.center, box.orientation
        carried = self.frames.get(path)
        if carried is None:
            raise WorldError(f"no prim {path} in this fake world")
        return compose(self.prim_pose(carried[0]), carried[1])

    def body_poses(self, paths) -> list[Pose]:
        return [self.prim_pose(path) for path in paths]

    def read_body_poses(self, paths):
        poses = self.body_poses(paths)
        return lambda: poses

    def prim_velocity(self, path: str) -> tuple[Vec3, Vec3]:
        self.prim_pose(path)
        return ZERO, ZERO

    # -- joints --

    def _articulation(self, path: str) -> dict:
        articulation = self.articulations.get(path)
        if articulation is None:
            raise WorldError(f"{path} is not an articulation of this fake world")
        return articulation

    def joint_names(self, articulation_path: str) -> tuple[str, ...]:
        return self._articulation(articulation_path)["names"]

    def joint_positions(self, articulation_path: str) -> tuple[float, ...]:
        return tuple(self._articulation(articulation_path)["positions"])

    def joint_velocities(self, articulation_path: str) -> tuple[float, ...]:
        return (0.0,) * len(self._articulation(articulation_path)["names"])

    def joint_paths(self, articulation_path: str) -> tuple[str, ...]:
        """Joints are children of the articulation root here."""
        root = self._articulation_root(articulation_path)
        return tuple(f"{root}/{name}" for name in self.articulations[root]["names"])

    def joint_efforts(self, articulation_path: str) -> tuple[float, ...]:
        """The efforts last commanded: joints here are ideal actuators that apply exactly what they are told."""
        return tuple(self.articulations[self._articulation_root(articulation_path)]["efforts"])

    def joint_dof_types(self, articulation_path: str) -> tuple[int, ...]:
        """Every joint of a fake articulation is revolute."""
        return (0,) * len(self.articulations[self._articulation_root(articulation_path)]["names"])

    def _articulation_root(self, path: str) -> str:
        """The articulation *path* is, or whose joint it names."""
        if path in self.articulations:
            return path
        root, _, name = path.rpartition("/")
        if root in self.articulations and name in self.articulations[root]["names"]:
            return root
        raise WorldError(f"{path} is not an articulation or joint of this fake world")

    def set_joint_targets(self, articulation_path: str, indices: Sequence[int], *,
                          positions: Sequence[float] | None = None, velocities: Sequence[float] | None = None,
                          efforts: Sequence[float] | None = None) -> None:
        articulation = self._articulation(articulation_path)
        count = len(articulation["names"])
        for slot, index in enumerate(indices):
            if not 0 <= index < count:
                raise WorldError(f"{articulation_path}: joint index {index} out of range (0..{count - 1})")
            if positions is not None:
                articulation["positions"][index] = float(positions[slot])
            if efforts is not None:
                articulation["efforts"][index] = float(efforts[slot])

    # -- attributes --

    def get_attribute(self, prim_path: str, name: str):
        if (prim_path, name) not in self.attributes:
            raise WorldError(f"{prim_path} has no attribute {name}")
        return self.attributes[(prim_path, name)]

    def set_attribute(self, prim_path: str, name: str, value) -> None:
        self.attributes[(prim_path, name)] = value

    def read_prim(self, prim_path: str, bounding_box: bool = False, time: float | None = None) -> Bundle:
        """The stage's prim with ``attributes`` set here as its live values; without a stage, the attributes
        set here (types from their values) and ``worldMatrix`` of a box or carried frame."""
        try:
            pose: Pose | None = self.prim_pose(prim_path)
        except WorldError:
            pose = None
        prim = self.stage.GetPrimAtPath(prim_path) if self.stage is not None and prim_path.startswith("/") else None
        if prim:
            from graphflow.usd.prim_bundle import prim_bundle

            return prim_bundle(prim, live=lambda name: self.attributes.get((prim_path, name)), world_pose=pose,
                               bounding_box=bounding_box, time=time)
        attributes = [BundleAttribute(name, type_name, value) for (path, name), value in self.attributes.items()
                      if path == prim_path and (type_name := type_of_value(value)) is not None]
        if pose is not None:
            attributes.append(BundleAttribute("worldMatrix", "matrixd[16]", pose_matrix(pose)))
        elif not attributes:
            raise WorldError(f"no prim {prim_path} in this fake world")
        return Bundle.of_prim(prim_path, "", tuple(attributes))

    # -- queries --

    def raycast(self, origin: Vec3, direction: Vec3, length: float) -> RayHit | None:
        norm = math.sqrt(sum(c * c for c in direction))
        if norm == 0.0:
            raise WorldError("a ray needs a non-zero direction")
        unit = as_vec3(c / norm for c in direction)
        self.rays.append((as_vec3(origin), unit, length))
        best: RayHit | None = None
        for box in self.boxes.values():
            hit = _ray_box(origin, unit, length, box)
            if hit is not None and (best is None or hit.distance < best.distance):
                best = hit
        return best

    def raycast_batch(self, origins, directions, length: float) -> list[RayHit | None]:
        return [self.raycast(origin, direction, length) for origin, direction in zip(origins, directions)]

    def contacts(self, path: str) -> list[Contact]:
        """Boxes overlapping or touching *path*'s box (colliding pairs only); no forces are simulated."""
        box = self._box(self.body_of(path) or path)
        found = []
        for other in self.boxes.values():
            if other is box or frozenset((box.path, other.path)) in self.no_collision:
                continue
            gaps = [abs(box.center[i] - other.center[i]) - box.half_extents[i] - other.half_extents[i]
                    for i in range(3)]
            if max(gaps) > 0.0:
                continue
            axis = max(range(3), key=lambda i: gaps[i])     # least penetration
            sign = 1.0 if box.center[axis] >= other.center[axis] else -1.0
            normal = as_vec3(sign if i == axis else 0.0 for i in range(3))
            point = as_vec3(other.center[i] + sign * other.half_extents[i] if i == axis else box.center[i]
                          for i in range(3))
            found.append(Contact(other.path, point, normal, gaps[axis], 0.0))
        return found

    # -- actions --

    def apply_force(self, path: str, force: Vec3, position: Vec3 | None = None) -> None:
        body = self.body_of(path) or path
        self._box(body)
        self._pending_forces.append((body, as_vec3(force), position))

    def gravity(self) -> Vec3:
        """Kinematic boxes do not fall; the vector is what sensors subtract (a stage's default)."""
        return (0.0, 0.0, -9.81)

    def gravity_enabled(self, prim_path: str) -> bool:
        return self._box(self.body_of(prim_path) or prim_path).gravity

    def set_gravity_enabled(self, prim_path: str, enabled: bool) -> None:
        self._box(self.body_of(prim_path) or prim_path).gravity = bool(enabled)

    def set_collision_between(self, prim_a: str, prim_b: str, enabled: bool) -> None:
        pair = frozenset((self.body_of(prim_a) or prim_a, self.body_of(prim_b) or prim_b))
        (self.no_collision.discard if enabled else self.no_collision.add)(pair)

    def prim_active(self, prim_path: str) -> bool:
        prim = self.stage.GetPrimAtPath(prim_path) if self.stage is not None else None
        if prim_path not in self.boxes and not prim:
            raise WorldError(f"no prim {prim_path} in this fake world")
        switched_off = any(prim_path == off or prim_path.startswith(off + "/") for off in self.inactive)
        return (not prim or prim.IsActive()) and not switched_off

    def set_prim_active(self, prim_path: str, active: bool) -> None:
        self.prim_active(prim_path)
        (self.inactive.discard if active else self.inactive.add)(prim_path)

    # -- animation (MoveTo*, RotateTo*, TranslateTo*, ScaleToSize): boxes placed in the world frame --

    def local_transform(self, prim_path: str):
        box = self._box(prim_path)
        return box.center, box.orientation, self.scales.get(prim_path, (1.0, 1.0, 1.0))

    def set_local_transform(self, prim_path: str, translation, orientation, scale) -> None:
        """A box moves and turns at once; its scale is recorded (``scales``), its size stays."""
        box = self._box(prim_path)
        x, y, z, w = (float(c) for c in orientation)
        box.center, box.orientation = as_vec3(translation), (x, y, z, w)
        self.scales[prim_path] = as_vec3(scale)


def _ray_box(origin: Vec3, unit: Vec3, length: float, box: Box) -> RayHit | None:
    """Slab test of a ray against an axis-aligned box: the entry point within *length* (0 when inside)."""
    if box.contains(origin):
        return RayHit(box.path, as_vec3(origin), as_vec3(-c for c in unit), 0.0)
    near, far, normal = 0.0, length, None
    for i in range(3):
        low, high = box.center[i] - box.half_extents[i], box.center[i] + box.half_extents[i]
        if unit[i] == 0.0:
            if not low <= origin[i] <= high:
                return None
            continue
        t_low, t_high = (low - origin[i]) / unit[i], (high - origin[i]) / unit[i]
        entry, exit_ = min(t_low, t_high), max(t_low, t_high)
        if entry > near:
            near = entry
            normal = as_vec3((-1.0 if unit[i] > 0 else 1.0) if j == i else 0.0 for j in range(3))
        far = min(far, exit_)
        if near > far:
            return None
    if normal is None:
        return None
    position = as_vec3(origin[i] + unit[i] * near for i in range(3))
    return RayHit(box.path, position, normal, near)
