"""The surface-gripper manager: one per world, updated right after every physics step.

It mirrors Isaac Sim's SurfaceGripperManager and its Python interface
(``open_gripper``, ``close_gripper``, ``set_gripper_action``, ... and their
``*_batch`` forms, ``set_write_to_usd``) plus GripperView-style run-time
properties. Grippers are every ``IsaacSurfaceGripper`` prim on the world's
stage; prims added or edited later are picked up through USD change notices.

The in-memory status is authoritative: it is written to USD (only with
``set_write_to_usd(True)``, into an anonymous session sub-layer) but never read
back, so the stale-status quirk of Isaac's ``onComponentChange`` (§2.10) does
not exist here.
"""
from __future__ import annotations

import logging
from typing import Iterable, Sequence

from graphflow.gripper import usd_schema
from graphflow.gripper.component import (
    GripperProperties,
    GripperStatus,
    SurfaceGripperComponent,
)
from graphflow.gripper.joints import attachment_point
from graphflow.world import RIGID

log = logging.getLogger(__name__)

ACTION_THRESHOLD = 0.3
SESSION_SUBLAYER_TAG = "anon_gripper_ops_"
_PROPERTY_NAMES = {usd_schema.MAX_GRIP_DISTANCE, usd_schema.RETRY_INTERVAL,
                   usd_schema.SHEAR_FORCE_LIMIT, usd_schema.COAXIAL_FORCE_LIMIT}


class SurfaceGripperManager:
    """Every surface gripper of one world, and Isaac's interface to them.

    It talks to the world only through ``graphflow.world.World``: grippers are
    read from ``world.stage``, holds made with ``world.attachments``.
    """

    def __init__(self, world):
        self.world = world
        self.attachments = world.attachments
        self.stage = world.stage
        self.write_to_usd = False
        self.components: dict[str, SurfaceGripperComponent] = {}
        self._actions: list[tuple] = []
        self._dirty_properties: set[str] = set()
        self._rescan = False
        self._session_layer = None
        self._gravity_off: set[str] = set()
        self._gravity_restore: dict = {}             # attachment handle -> held body whose gravity it switched off
        self._written_gripped: dict[str, list[str]] = {}
        usd_schema.register_schema()
        from pxr import Tf, Usd

        self._listener = Tf.Notice.Register(Usd.Notice.ObjectsChanged, self._on_objects_changed, self.stage)
        self._scan()

    # -- Isaac's interface --

    def open_gripper(self, path: str) -> bool:
        component = self._component(path)
        return component is not None and component.set_status(GripperStatus.OPEN)

    def close_gripper(self, path: str) -> bool:
        component = self._component(path)
        return component is not None and component.set_status(GripperStatus.CLOSED)

    def set_gripper_action(self, path: str, action: float) -> bool:
        """``action < -0.3`` opens, ``> 0.3`` closes (strict), anything between does nothing and returns False."""
        if action < -ACTION_THRESHOLD:
            return self.open_gripper(path)
        if action > ACTION_THRESHOLD:
            return self.close_gripper(path)
        return False

    def get_gripper_status(self, path: str) -> GripperStatus:
        component = self._component(path)
        if component is None:
            log.warning("Gripper not found: %s", path)
            return GripperStatus.OPEN
        return component.status

    def get_gripped_objects(self, path: str) -> list[str]:
        component = self._component(path)
        return [] if component is None else component.gripped_objects()

    def open_gripper_batch(self, paths: Sequence[str]) -> list[bool]:
        return [self.open_gripper(path) for path in paths]

    def close_gripper_batch(self, paths: Sequence[str]) -> list[bool]:
        return [self.close_gripper(path) for path in paths]

    def set_gripper_action_batch(self, paths: Sequence[str], actions: Sequence[float]) -> list[bool]:
        """One action per path; mismatched lengths do nothing and return ``[]`` (as Isaac)."""
        if len(paths) != len(actions):
            return []
        return [self.set_gripper_action(path, action) for path, action in zip(paths, actions)]

    def get_gripper_status_batch(self, paths: Sequence[str]) -> list[GripperStatus]:
        return [self.get_gripper_status(path) for path in paths]

    def get_gripped_objects_batch(self, paths: Sequence[str]) -> list[list[str]]:
        return [self.get_gripped_objects(path) for path in paths]

    def set_write_to_usd(self, enabled: bool) -> None:
        self.write_to_usd = bool(enabled)

    # -- GripperView-style properties --

    def set_gripper_properties(self, paths: str | Iterable[str], *, max_grip_distance=None,
                               coaxial_force_limit=None, shear_force_limit=None, retry_interval=None) -> None:
        """Set properties at run time (None leaves one as is); also authored on the gripper prims, on the
        session sub-layer: never on the stage file's layer, which later stages opened in this process share."""
        from pxr import Usd

        for path in [paths] if isinstance(paths, str) else list(paths):
            component = self._require(path)
            with Usd.EditContext(self.stage, self._edit_layer()):
                usd_schema.set_gripper_properties(
                    self.stage.GetPrimAtPath(path), max_grip_distance=max_grip_distance,
                    coaxial_force_limit=coaxial_force_limit, shear_force_limit=shear_force_limit,
                    retry_interval=retry_interval)
            self._read_properties(component)

    def get_gripper_properties(self, path: str) -> tuple[float, float, float, float]:
        """``(maxGripDistance, coaxialForceLimit, shearForceLimit, retryInterval)`` as GripperView returns them."""
        properties = self._require(path).properties
        return (properties.max_grip_distance, properties.coaxial_force_limit,
                properties.shear_force_limit, properties.retry_interval)

    def set_break_limits(self, path: str, force_limit: float, torque_limit: float) -> None:
        """Break a grip when the force or torque magnitude on an attachment point exceeds a limit
        (the legacy gripper's joint break force and torque; <= 0 disables, not stored in USD)."""
        properties = self._require(path).properties
        properties.force_limit, properties.torque_limit = float(force_limit), float(torque_limit)

    def set_reach_from_ray_origin(self, path: str, enabled: bool) -> None:
        """Count maxGripDistance from where the ray leaves the gripper's own body, not from the joint
        origin (the legacy gripper's grip_threshold)."""
        self._require(path).properties.reach_from_ray_origin = bool(enabled)

    def set_gravity_disabled_while_held(self, path: str, disabled: bool) -> None:
        """Cancel gravity on objects while this gripper holds them (the legacy gripper's ``disable_gravity``)."""
        (self._gravity_off.add if disabled else self._gravity_off.discard)(path)

    def component(self, path: str) -> SurfaceGripperComponent:
        return self._require(path)

    # -- world hooks --

    def after_step(self, dt: float) -> None:
        """The world service's step (after the world's attachments): every gripper's update, then queued attach/detach."""
        self._refresh()
        for component in self.components.values():
            component.on_physics_step(dt)
        self._execute_actions()
        if self.write_to_usd:
            self._write_gripped_objects()

    def reset(self) -> None:
        """The world was reset: every attachment is gone, grippers are Open, USD writes are discarded."""
        self._actions.clear()
        self._gravity_restore.clear()
        for component in self.components.values():
            component.stop()
        self._written_gripped.clear()
        if self._session_layer is not None:
            self._session_layer.Clear()

    # -- internals --

    def _component(self, path: str) -> SurfaceGripperComponent | None:
        self._refresh()
        return self.components.get(path)

    def _require(self, path: str) -> SurfaceGripperComponent:
        component = self._component(path)
        if component is None:
            raise KeyError(f"no IsaacSurfaceGripper prim at {path}")
        return component

    def _scan(self) -> None:
        present = usd_schema.find_surface_grippers(self.stage)
        for path in list(self.components):
            if path not in present:
                self.components.pop(path).update_open()
        for path in present:
            if path not in self.components:
                self.components[path] = self._build(path)
            elif not self.components[path].active:
                self.components[path].replace_points(self._points(path))
        self._execute_actions()

    def _build(self, path: str) -> SurfaceGripperComponent:
        component = SurfaceGripperComponent(
            path=path, points=self._points(path), world=self.world, queue=self._actions.append,
            properties=GripperProperties(), on_status_change=self._status_changed,
            on_clearance_change=self._clearance_changed)
        self._read_properties(component)
        return component

    def _points(self, path: str):
        prim = self.stage.GetPrimAtPath(path)
        relationship = prim.GetRelationship(usd_schema.ATTACHMENT_POINTS)
        described = self.world.attachment_joints
        points = []
        for target in relationship.GetTargets() if relationship else []:
            point = attachment_point(self.stage, target.pathString, described)
            if point is None:
                continue
            if self.world.body_of(point.body0_path) is None:
                log.warning("Gripper %s has no joint at attachment point %s", path, target.pathString)
                continue
            points.append(point)
        return points

    def _read_properties(self, component: SurfaceGripperComponent) -> None:
        prim = self.stage.GetPrimAtPath(component.path)
        current = component.properties
        current.max_grip_distance = usd_schema.read_float(prim, usd_schema.MAX_GRIP_DISTANCE, current.max_grip_distance)
        current.retry_interval = usd_schema.read_float(prim, usd_schema.RETRY_INTERVAL, current.retry_interval)
        current.shear_force_limit = usd_schema.read_float(prim, usd_schema.SHEAR_FORCE_LIMIT, current.shear_force_limit)
        current.coaxial_force_limit = usd_schema.read_float(prim, usd_schema.COAXIAL_FORCE_LIMIT,
                                                            current.coaxial_force_limit)

    def _on_objects_changed(self, notice, _stage) -> None:
        for path in notice.GetResyncedPaths():
            if path.IsPrimPath() or path.name == usd_schema.ATTACHMENT_POINTS:
                self._rescan = True
        for path in notice.GetChangedInfoOnlyPaths():
            if path.IsPropertyPath() and path.name in _PROPERTY_NAMES:
                self._dirty_properties.add(path.GetPrimPath().pathString)
            elif path.IsPropertyPath() and path.name == usd_schema.ATTACHMENT_POINTS:
                self._rescan = True

    def _refresh(self) -> None:
        if self._rescan:
            self._rescan = False
            self._scan()
        while self._dirty_properties:
            component = self.components.get(self._dirty_properties.pop())
            if component is not None:
                self._read_properties(component)

    def _execute_actions(self) -> None:
        actions = list(self._actions)
        self._actions.clear()
        for action in actions:
            component, index = action[1], action[2]
            if action[0] == "attach":
                point = component.points[index]
                handle = self.attachments.attach(point.body0_path, point.local_pose0, action[3],
                                                 point.compliance or RIGID)
                if handle is None:
                    continue
                component.handles[index] = handle
                if component.path in self._gravity_off:
                    self._switch_gravity_off(handle)
            else:
                handle = component.handles.pop(index, None)
                if handle is not None:
                    self._detach(handle)

    def _switch_gravity_off(self, handle) -> None:
        """Gravity off for the held body while held (restored on its last detach, if it was on)."""
        body = self.attachments.target_of(handle)
        if body in self._gravity_restore.values() or self.world.gravity_enabled(body):
            self.world.set_gravity_enabled(body, False)
            self._gravity_restore[handle] = body

    def _detach(self, handle) -> None:
        self.attachments.detach(handle)
        body = self._gravity_restore.pop(handle, None)
        if body is not None and body not in self._gravity_restore.values():
            self.world.set_gravity_enabled(body, True)

    # -- write-back to USD (session sub-layer, discarded on reset) --

    def _edit_layer(self):
        from pxr import Sdf

        if self._session_layer is None:
            self._session_layer = Sdf.Layer.CreateAnonymous(SESSION_SUBLAYER_TAG)
            self.stage.GetSessionLayer().subLayerPaths.append(self._session_layer.identifier)
        return self._session_layer

    def _status_changed(self, component: SurfaceGripperComponent) -> None:
        if self.write_to_usd:
            from pxr import Sdf, Usd

            with Usd.EditContext(self.stage, self._edit_layer()):
                prim = self.stage.GetPrimAtPath(component.path)
                prim.CreateAttribute(usd_schema.STATUS, Sdf.ValueTypeNames.Token, False).Set(component.status.token)

    def _clearance_changed(self, point) -> None:
        if self.write_to_usd:
            from pxr import Usd

            with Usd.EditContext(self.stage, self._edit_layer()):
                usd_schema.apply_attachment_point_api(self.stage.GetPrimAtPath(point.joint_path),
                                                      clearance_offset=point.clearance_offset)

    def _write_gripped_objects(self) -> None:
        from pxr import Sdf, Usd, UsdPhysics

        for path, component in self.components.items():
            gripped = component.gripped_objects()
            if self._written_gripped.get(path, []) == gripped:
                continue
            self._written_gripped[path] = gripped
            targets = [Sdf.Path(p) for p in gripped]
            with Usd.EditContext(self.stage, self._edit_layer()):
                prim = self.stage.GetPrimAtPath(path)
                relationship = prim.CreateRelationship(usd_schema.GRIPPED_OBJECTS, False)
                relationship.SetTargets(targets) if targets else relationship.ClearTargets(True)
                if component.points:
                    body0 = self.stage.GetPrimAtPath(component.points[0].body0_path)
                    pairs = UsdPhysics.FilteredPairsAPI.Apply(body0).CreateFilteredPairsRel()
                    pairs.SetTargets(targets) if targets else pairs.ClearTargets(True)


def manager_for(world) -> SurfaceGripperManager:
    """The world's surface-gripper manager: a service of the world, created on first use."""
    return world.services.require(SurfaceGripperManager, lambda: SurfaceGripperManager(world))
