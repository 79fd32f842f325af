"""One surface gripper's status machine, as Isaac Sim's SurfaceGripperComponent (reference §2.4-2.11).

The component knows nothing about PyBullet: it asks its world, through the
declared interface (``graphflow.world.World``), for raycasts and body
identities, and the world's ``attachments`` for attachment frames and forces
(``graphflow.testing.fake_world.FakeWorld`` serves the tests). Attach and detach requests are queued
on the manager and carried out at the end of the next physics-step update, so
a joint created during step *k*'s update is active for step *k+1* (§2.1).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from enum import IntEnum
from typing import Any, Callable, Sequence

from graphflow.poses import AXIS_VECTORS, Pose, quat_rotate
from graphflow.world import AXIS_NAMES, Attachments, AxisCompliance, World, WorldError

SETTLING_DELAY = 10          # physics steps before force checks after an attach or break (m_settlingDelay)
SELF_HIT_STEP = 0.001        # m the ray origin advances past the gripper's own body
SELF_HIT_MAX_STEPS = 1000    # give up after 1 m of self hits (Isaac loops without bound)
PROBE_RANGE = 1.0            # m searched beyond the reach to name the nearest surface when a close fails
REASON_POINTS_LISTED = 3     # attachment points named in a close-failure reason; the rest are counted
SETTLING = "settling"        # a close-failure note: the point did not cast, it was settling after its last grip


STATUS_TOKENS = ("Open", "Closing", "Closed")   # GripperStatus by value: the status's token (a recorder's lookup)


class GripperStatus(IntEnum):
    """Isaac's enum order: Open=0, Closing=1, Closed=2 (the C++ and binding order, not the online doc)."""

    OPEN = 0
    CLOSING = 1
    CLOSED = 2

    @property
    def token(self) -> str:
        return STATUS_TOKENS[self]

    @classmethod
    def from_token(cls, token: str | None) -> "GripperStatus":
        """Unknown or empty tokens read as Open (``GripperStatusFromToken``)."""
        return {"Closing": cls.CLOSING, "Closed": cls.CLOSED}.get(token or "", cls.OPEN)


def compliance_from_joint(limits: dict, drives: dict) -> tuple[AxisCompliance, ...]:
    """Per-axis compliance from a D6 joint's ``limits`` (objects with ``low``/``high``) and ``drives``."""
    axes = []
    for name in AXIS_NAMES:
        limit = limits.get(name)
        drive = drives.get(name)
        axes.append(AxisCompliance(
            lower=limit.low if limit is not None else float("-inf"),
            upper=limit.high if limit is not None else float("inf"),
            stiffness=max(0.0, float(drive.stiffness)) if drive is not None else 0.0,
            damping=max(0.0, float(drive.damping)) if drive is not None else 0.0))
    return tuple(axes)


@dataclass
class AttachmentPoint:
    """One D6 attachment joint: where its frame sits on the gripper body and how it complies."""

    joint_path: str
    body0_path: str
    local_pose0: Pose               # joint frame in body0's frame, scale applied
    forward_axis: str = "X"
    clearance_offset: float = 0.0
    compliance: Sequence[AxisCompliance] | None = None    # per axis transX..rotZ; None = rigid
    settle: int = 0

    def frame_direction(self, frame: Pose):
        return quat_rotate(frame[1], AXIS_VECTORS[self.forward_axis])


@dataclass
class GripperProperties:
    """Run-time properties; defaults are the schema fallbacks (see usd_schema)."""

    max_grip_distance: float = 0.01
    retry_interval: float = 0.0
    shear_force_limit: float = -1.0
    coaxial_force_limit: float = -1.0
    force_limit: float = -1.0      # legacy gripper: break when |F| exceeds it (not a USD property)
    torque_limit: float = -1.0     # legacy gripper: break when |T| exceeds it (not a USD property)
    reach_from_ray_origin: bool = False   # legacy gripper: the reach counts from where the ray leaves the parent


@dataclass
class GripEvents:
    """Counters the node compares between computes to see grips end."""

    force_breaks: int = 0          # attachment points released by a force limit
    releases: int = 0              # opens that let go of at least one object


@dataclass
class SurfaceGripperComponent:
    path: str
    points: list[AttachmentPoint]
    world: "World"
    queue: Callable[[tuple], None]           # the manager's action queue
    properties: GripperProperties = field(default_factory=GripperProperties)
    on_status_change: Callable[["SurfaceGripperComponent"], None] | None = None
    on_clearance_change: Callable[[AttachmentPoint], None] | None = None
    status: GripperStatus = GripperStatus.OPEN
    retry_elapsed: float = 0.0
    retry_active: bool = False
    events: GripEvents = field(default_factory=GripEvents)
    reason: str = ""       # why the last close failed or the last grip ended ('' since a close began)

    def __post_init__(self):
        self.inactive: set[int] = set(range(len(self.points)))
        self.active: dict[int, str] = {}        # index -> gripped object path
        self.handles: dict[int, Any] = {}        # index -> executed attachment handle
        # joint path -> (reach, nearest hit (prim, m) or None) of its first empty ray since the close began,
        # or None when it saw only the gripper's own body: where the arm was when the close was commanded
        self.misses: dict[str, tuple | str | None] = {}
        # (physics step index, handle -> rigid-row force) as check_force_limits read them on that step:
        # checked_force answers from it until the next step instead of asking the world again
        self._step_forces: tuple[int, dict] = (-1, {})

    # -- commands (setGripperStatus) --

    def set_status(self, requested: GripperStatus) -> bool:
        if requested == self.status:
            return True
        if requested == GripperStatus.OPEN:
            held = sorted(set(self.active.values()))
            if held:
                self.reason = f"released {', '.join(held)} by Open"
            elif not self.reason:   # a force break or failed close already says why nothing is held
                self.reason = "close cancelled by Open" + self._miss_details()   # with how far each ray missed
            self.update_open()
            self._set(GripperStatus.OPEN)
            self.retry_active = False
        elif requested == GripperStatus.CLOSED and self.status != GripperStatus.CLOSING:
            self.reason = ""
            self.misses.clear()
            self._set(GripperStatus.CLOSING)
            self.retry_active = True
            self.update_closed()
            if self.properties.retry_interval > 0:
                self.retry_elapsed = 0.0
            else:
                self.retry_active = False
        return True

    # -- per physics step --

    def on_physics_step(self, dt: float) -> None:
        for index in self.inactive:
            if self.points[index].settle > 0:
                self.points[index].settle -= 1
        if (self.status == GripperStatus.CLOSING and self.properties.retry_interval > 0
                and self.retry_active and self.inactive):
            self.retry_elapsed += dt
            if self.retry_elapsed > self.properties.retry_interval:
                self.retry_active = False
                self.retry_elapsed = 0.0
        if self.status in (GripperStatus.CLOSED, GripperStatus.CLOSING):
            if self.retry_active or self.active:
                self.update_closed()
            else:
                self.update_open()
        else:
            self.update_open()

    def update_closed(self) -> None:
        if not self.points:
            return
        if self.inactive and (self.status == GripperStatus.CLOSING or self.retry_active):
            self.find_objects_to_grip()
        self.check_force_limits()
        if not self.inactive:
            self._set(GripperStatus.CLOSED)
            self.retry_elapsed = 0.0
        elif self.retry_active:
            self._set(GripperStatus.CLOSING)
        elif not self.active:
            self._set(GripperStatus.OPEN)

    def update_open(self) -> None:
        if self.active or self.status != GripperStatus.OPEN:
            if self.active:
                self.events.releases += 1
            for index in range(len(self.points)):
                self.queue(("detach", self, index))
            self.active.clear()
            self.inactive = set(range(len(self.points)))
        self._set(GripperStatus.OPEN)

    def find_objects_to_grip(self) -> None:
        newly_active = []
        for index in sorted(self.inactive):
            point = self.points[index]
            if point.settle > 0:
                point.settle -= 1
                self.misses.setdefault(point.joint_path, SETTLING)
                continue
            frame = self._attachments.frame(point.body0_path, point.local_pose0)
            if frame is None:
                continue
            target = self._cast(point, frame)
            if target is not None:
                self.queue(("attach", self, index, target))
                self.active[index] = target
                newly_active.append(index)
        for index in newly_active:
            self.inactive.discard(index)
            self.points[index].settle = SETTLING_DELAY

    def _cast(self, point: AttachmentPoint, frame: Pose) -> str | None:
        """Isaac's ray loop: from the clearance offset, stepping 1 mm past hits on the gripper's own body.

        The backend reports a body the ray starts inside at distance 0 (PhysX's scene query): an object
        between the joint origin and the clearance point is gripped; a ray starting inside the
        gripper's own body steps out of it 1 mm at a time.
        """
        direction = point.frame_direction(frame)
        clearance = point.clearance_offset
        for _ in range(SELF_HIT_MAX_STEPS):
            origin = tuple(frame[0][i] + direction[i] * clearance for i in range(3))
            length = self.properties.max_grip_distance - (0.0 if self.properties.reach_from_ray_origin else clearance)
            hit = self.world.raycast(origin, direction, length if length > 0 else 0.001)
            if hit is None or not hit.prim_path:
                if self.misses.get(point.joint_path, SETTLING) == SETTLING:   # first real miss of this close
                    reach = length if length > 0 else 0.001
                    self.misses[point.joint_path] = (reach, self._nearest_hit(origin, direction))
                return None
            hit_path = hit.prim_path
            if self.world.same_body(hit_path, point.body0_path):
                clearance += SELF_HIT_STEP
                continue
            if clearance > 0 and clearance != point.clearance_offset:
                point.clearance_offset = clearance
                if self.on_clearance_change is not None:
                    self.on_clearance_change(point)
            return hit_path
        self.misses.setdefault(point.joint_path, None)   # nothing but the gripper's own body for 1 m
        return None

    def check_force_limits(self) -> None:
        shear_limit = self.properties.shear_force_limit
        coaxial_limit = self.properties.coaxial_force_limit
        force_limit, torque_limit = self.properties.force_limit, self.properties.torque_limit
        step_forces: dict = {}
        self._step_forces = (self.world.step_index, step_forces)
        if self.status == GripperStatus.OPEN or max(shear_limit, coaxial_limit, force_limit, torque_limit) <= 0:
            return
        for index in sorted(self.active):
            point = self.points[index]
            if point.settle > 0:
                point.settle -= 1
                continue
            handle = self.handles.get(index)
            if handle is None:
                continue
            attachments = self._attachments
            force = step_forces[handle] = attachments.force_on_gripper(handle)
            frame = attachments.frame(point.body0_path, point.local_pose0)
            if frame is None:
                continue
            direction = point.frame_direction(frame)
            coaxial = sum(force[i] * direction[i] for i in range(3))
            shear_squared = sum((force[i] - direction[i] * coaxial) ** 2 for i in range(3))
            broken = None
            if coaxial_limit > 0 and coaxial > coaxial_limit:
                broken = f"coaxial force {coaxial:.1f} N > limit {coaxial_limit:g} N"
            elif shear_limit > 0 and shear_squared > shear_limit * shear_limit:
                broken = f"shear force {math.sqrt(shear_squared):.1f} N > limit {shear_limit:g} N"
            elif force_limit > 0 and (total := self.checked_force(handle)) > force_limit:
                broken = f"force {total:.1f} N > limit {force_limit:g} N"
            elif torque_limit > 0 and (torque := _norm(attachments.torque_on_gripper(handle))) > torque_limit:
                broken = f"torque {torque:.1f} N m > limit {torque_limit:g} N m"
            if broken is not None:
                self.reason = f"grip on {self.active[index]} broken by {broken} at {point.joint_path}"
                self.queue(("detach", self, index))
                del self.active[index]
                self.inactive.add(index)
                point.settle = SETTLING_DELAY
                self.events.force_breaks += 1

    # -- queries --

    @property
    def _attachments(self) -> Attachments:
        attachments = self.world.attachments
        if attachments is None:
            raise WorldError("a surface gripper needs a world with bodies to attach (this world has none)")
        return attachments

    def checked_force(self, handle) -> float:
        """|F| on the gripper as its limits see it (N): the whole force for a legacy ``forceLimit`` (the springs'
        share included: the legacy joint breaks on it), else the rigid rows' (what the coaxial and shear
        limits split); read once a physics step (the trace samples it every tick while the check ran already)."""
        rigid_rows_only = self.properties.force_limit <= 0
        step, forces = self._step_forces
        if rigid_rows_only and handle in forces and step == self.world.step_index:
            return _norm(forces[handle])
        return _norm(self._attachments.force_on_gripper(handle, rigid_rows_only))

    def gripped_objects(self) -> list[str]:
        """Objects held by executed attachments, each once, sorted (Isaac returns an unordered set)."""
        return sorted({self.active[i] for i in self.active if i in self.handles})

    def replace_points(self, points: list[AttachmentPoint]) -> None:
        """New attachment points (the relationship was edited); only while nothing is attached."""
        self.points = points
        self.inactive = set(range(len(points)))
        self.handles.clear()

    def stop(self) -> None:
        """Forget every attachment (Isaac's onStop), without queuing detaches: the world is being reset."""
        self.active.clear()
        self.handles.clear()
        self._step_forces = (-1, {})
        self.inactive = set(range(len(self.points)))
        self.status = GripperStatus.OPEN
        self.retry_active = False
        self.retry_elapsed = 0.0
        self.reason = ""
        self.misses.clear()
        for point in self.points:
            point.settle = 0

    def _set(self, status: GripperStatus) -> None:
        if status != self.status:
            if status == GripperStatus.OPEN and not self.reason:
                self.reason = self._close_failure()
            self.status = status
            if self.on_status_change is not None:
                self.on_status_change(self)


    def _close_failure(self) -> str:
        """Why a close ended Open without a command or a force break: the retry window and every empty ray."""
        retry = self.properties.retry_interval
        prefix = f"close failed: retry interval {retry:g} s elapsed" if retry > 0 else "close failed"
        return prefix + self._miss_details()

    def _miss_details(self) -> str:
        """"; <joint>: no surface within <reach> m (nearest hit ...)" for every empty ray since the close, or ""."""
        missed = [self.points[i].joint_path for i in sorted(self.inactive) if self.points[i].joint_path in self.misses]
        if not missed:
            return ""
        details = []
        for joint_path in missed[:REASON_POINTS_LISTED]:
            miss = self.misses[joint_path]
            if isinstance(miss, str):     # SETTLING
                details.append(f"{joint_path}: still settling after its last grip ({SETTLING_DELAY} physics steps)")
                continue
            if miss is None:
                details.append(f"{joint_path}: only the gripper's own body within {SELF_HIT_STEP * SELF_HIT_MAX_STEPS:g} m")
                continue
            reach, nearest = miss
            seen = (f"nearest hit {nearest[0]} at {nearest[1]:.4f} m" if nearest is not None
                    else f"nothing within {PROBE_RANGE:g} m")
            details.append(f"{joint_path}: no surface within {reach:.4f} m ({seen})")
        more = len(missed) - REASON_POINTS_LISTED
        return "; " + "; ".join(details) + (f"; and {more} more attachment points" if more > 0 else "")

    def _nearest_hit(self, origin, direction) -> tuple[str, float] | None:
        """What the ray would hit beyond its reach and how far along it: (prim, m), or None within PROBE_RANGE."""
        hit = self.world.raycast(origin, direction, PROBE_RANGE)
        return None if hit is None or not hit.prim_path else (hit.prim_path, hit.distance)


def _norm(vector) -> float:
    return math.sqrt(sum(c * c for c in vector))
