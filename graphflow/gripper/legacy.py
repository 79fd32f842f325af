"""The tutorials' ``SurfaceGripper(end_effector_prim_path, translate, direction, ...)`` on the same runtime.

Isaac Sim 4.x's Python gripper (reference §4.1) built a Dynamic-Control D6
joint at ``parent * offset`` and raycast along the end effector's +X. Here
``initialize(world)`` authors the equivalent on the stage's *session layer*
(nothing is saved with the stage): an ``IsaacSurfaceGripper`` under the end
effector and one D6 attachment joint ``<ee>/d6FixedJoint``:

* ``translate``/``direction``: the joint sits ``translate`` along the end
  effector's x, y or z; its frame keeps the end effector's orientation, so
  the ray always points along the end effector's +X (as the legacy C++).
* ``grip_threshold``: the reach (``maxGripDistance``), from the joint origin, or where the joint
  origin lies inside the end effector, from where the ray leaves it (the origin steps out 1 mm at
  a time while the ray hits the end effector, as the legacy C++ did).
* ``force_limit``/``torque_limit``: the joint's break force and torque
  (magnitudes on the attachment point); ``update()`` then opens the gripper.
* ``kp``/``kd``: stiffness and damping of the joint's translations (the
  legacy joint's soft limits at zero) and of its two bending axes.
* ``bend_angle``: if > 0, the two bending axes (rotations about the end
  effector's Y and Z) are free within ``±bend_angle``; otherwise fixed. The
  twist about the ray is always fixed.
* ``disable_gravity``: gravity is off for the object while it is held.

The gripper keeps trying while closing (the legacy ``attempting`` flag) until
``open()``; ``update()`` must be called every step (after ``world.step()``),
as Isaac's tasks do, so a grip broken by a force limit ends with ``open()``.
"""
from __future__ import annotations

import logging
import math

from graphflow.gripper.component import GripperStatus
from graphflow.gripper.manager import SurfaceGripperManager, manager_for
from graphflow.gripper.usd_schema import (
    apply_attachment_point_api,
    create_surface_gripper,
)

log = logging.getLogger(__name__)

_DIRECTIONS = ("x", "y", "z")


class SurfaceGripper:
    """A suction gripper on an end-effector prim, configured by the legacy tutorial's parameters."""

    def __init__(self, end_effector_prim_path: str, translate: float = 0, direction: str = "x",
                 grip_threshold: float = 0.01, force_limit: float = 1.0e6, torque_limit: float = 1.0e4,
                 bend_angle: float = math.pi / 24, kp: float = 1.0e2, kd: float = 1.0e2,
                 disable_gravity: bool = True):
        if direction not in _DIRECTIONS:
            raise ValueError(f"direction must be one of 'x', 'y', 'z', got {direction!r}")
        for name, value in (("grip_threshold", grip_threshold), ("force_limit", force_limit),
                            ("torque_limit", torque_limit), ("bend_angle", bend_angle), ("kp", kp), ("kd", kd)):
            if not isinstance(value, (int, float)) or math.isnan(value) or value < 0:
                raise ValueError(f"{name} must be a number >= 0, got {value!r}")
        if not isinstance(translate, (int, float)) or not math.isfinite(translate):
            raise ValueError(f"translate must be a finite number, got {translate!r}")
        self.end_effector_prim_path = end_effector_prim_path
        self.translate = float(translate)
        self.direction = direction
        self.grip_threshold = float(grip_threshold)
        self.force_limit = float(force_limit)
        self.torque_limit = float(torque_limit)
        self.bend_angle = float(bend_angle)
        self.kp = float(kp)
        self.kd = float(kd)
        self.disable_gravity = bool(disable_gravity)
        self.manager: SurfaceGripperManager | None = None
        self.gripper_path = ""      # set by initialize(), with the manager
        self._default_opened: bool | None = None
        self._num_dofs: int | None = None
        self._breaks_seen = 0

    # -- set-up --

    def initialize(self, world, articulation_num_dofs: int | None = None) -> None:
        """Author the gripper on the world's stage (session layer) and register it with the world's manager."""
        from pxr import Gf, Sdf, Usd, UsdPhysics

        stage = world.stage
        if not stage.GetPrimAtPath(self.end_effector_prim_path):
            raise ValueError(f"end_effector_prim_path: no prim at {self.end_effector_prim_path}")
        self._num_dofs = articulation_num_dofs
        with Usd.EditContext(stage, stage.GetSessionLayer()):
            joint = UsdPhysics.Joint.Define(stage, f"{self.end_effector_prim_path}/d6FixedJoint")
            joint.CreateBody0Rel().SetTargets([Sdf.Path(self.end_effector_prim_path)])
            offset = [0.0, 0.0, 0.0]
            offset[_DIRECTIONS.index(self.direction)] = self.translate
            joint.CreateLocalPos0Attr(Gf.Vec3f(*offset))
            joint.CreateLocalRot0Attr(Gf.Quatf(1.0))
            joint.CreateExcludeFromArticulationAttr(True)
            self._author_axes(joint.GetPrim())
            apply_attachment_point_api(joint.GetPrim(), forward_axis="X", clearance_offset=0.0)
            gripper = create_surface_gripper(stage, self.end_effector_prim_path)
            gripper.GetRelationship("isaac:attachmentPoints").SetTargets([joint.GetPath()])
        self.gripper_path = gripper.GetPath().pathString
        self.manager = manager = manager_for(world)
        manager.set_gripper_properties(self.gripper_path, max_grip_distance=self.grip_threshold,
                                            coaxial_force_limit=-1.0, shear_force_limit=-1.0,
                                            retry_interval=math.inf)
        manager.set_break_limits(self.gripper_path, self.force_limit, self.torque_limit)
        manager.set_reach_from_ray_origin(self.gripper_path, True)
        manager.set_gravity_disabled_while_held(self.gripper_path, self.disable_gravity)
        self._breaks_seen = manager.component(self.gripper_path).events.force_breaks
        if self._default_opened is None:
            self._default_opened = not self.is_closed()

    def _author_axes(self, prim) -> None:
        """Translations: springs kp/kd about the attach pose; bending: ±bend_angle with kp/kd; twist locked."""
        from pxr import UsdPhysics

        for axis in ("transX", "transY", "transZ", "rotX", "rotY", "rotZ"):
            bends = self.bend_angle > 0 and axis in ("rotY", "rotZ")
            if axis.startswith("rot") and not bends:
                limit = UsdPhysics.LimitAPI.Apply(prim, axis)
                limit.CreateLowAttr(1.0)
                limit.CreateHighAttr(-1.0)
                continue
            if bends:
                limit = UsdPhysics.LimitAPI.Apply(prim, axis)
                limit.CreateLowAttr(-math.degrees(self.bend_angle))
                limit.CreateHighAttr(math.degrees(self.bend_angle))
            per_usd_unit = math.radians(1.0) if bends else 1.0     # USD angular drives are per degree
            drive = UsdPhysics.DriveAPI.Apply(prim, axis)
            drive.CreateStiffnessAttr(self.kp * per_usd_unit)
            drive.CreateDampingAttr(self.kd * per_usd_unit)

    # -- the legacy interface --

    def _require(self) -> SurfaceGripperManager:
        if self.manager is None:
            raise RuntimeError("call initialize(world) first")
        return self.manager

    def close(self) -> None:
        manager = self._require()
        if not self.is_closed():
            manager.close_gripper(self.gripper_path)
            if not self.is_closed():
                log.warning("gripper didn't close successfully")

    def open(self) -> None:
        manager = self._require()
        was_closed = self.is_closed()
        manager.open_gripper(self.gripper_path)
        if not was_closed:
            log.warning("gripper didn't open successfully")

    def update(self) -> None:
        """Open after a force or torque limit broke the grip ("Gripper Constraint is Broken")."""
        manager = self._require()
        breaks = manager.component(self.gripper_path).events.force_breaks
        if breaks > self._breaks_seen:
            self._breaks_seen = breaks
            log.warning("Gripper Constraint is Broken")
            manager.open_gripper(self.gripper_path)

    def is_closed(self) -> bool:
        return self._require().get_gripper_status(self.gripper_path) == GripperStatus.CLOSED

    def gripped_objects(self) -> list[str]:
        return self._require().get_gripped_objects(self.gripper_path)

    def set_default_state(self, opened: bool) -> None:
        self._default_opened = bool(opened)

    def get_default_state(self) -> dict:
        return {"opened": self._default_opened}

    def post_reset(self) -> None:
        """After a world reset: back to the default state (open, or close again)."""
        self._breaks_seen = self._require().component(self.gripper_path).events.force_breaks
        if self._default_opened:
            self.open()
        else:
            self.close()

    def forward(self, action: str) -> tuple:
        """``"open"`` or ``"close"``; returns joint positions of ``None`` for every DOF (the gripper drives none)."""
        if self._num_dofs is None:
            raise ValueError("forward needs articulation_num_dofs, given to initialize()")
        if action == "open":
            self.open()
        elif action == "close":
            self.close()
        else:
            raise ValueError(f"action must be 'open' or 'close', got {action!r}")
        return (None,) * self._num_dofs
