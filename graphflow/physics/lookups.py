"""Prim path -> built PyBullet object, and the poses that follow from it: a mixin of ``PyBulletWorld``.

A mixin rather than a helper object so the world's hot paths (``prim_pose``,
``joint_positions``) reach these with one method lookup. It uses the world's
``client``, ``description``, ``stage``, ``scene`` and ``_offsets`` (a cache
cleared on every rebuild).
"""
from __future__ import annotations

from array import array
from functools import partial
from typing import Any, Callable, Iterable

from graphflow.physics.handles import ArticulationHandle, BodyHandle, BuiltScene
from graphflow.poses import IDENTITY_POSE, Pose, compose, relative
from graphflow.usd.description import StageDescription
from graphflow.world import WorldError

# body_poses' plan for one list of paths (see _pose_plan)
PosePlan = tuple[list[int], list[tuple[int, list[int]]], list[int], list[Pose], list[tuple[array, Pose] | None]]


class SceneLookups:
    """Finding bodies, colliders and articulations by prim path; their world poses."""

    # what the mixin uses of the world (``PyBulletWorld`` sets them)
    client: Any                                   # a pybullet BulletClient: pybullet has no type information
    description: StageDescription
    stage: Any                                    # the pxr Usd.Stage or None: pxr has no type information
    scene: BuiltScene
    _offsets: dict[str, tuple[str | None, Pose]]
    _pose_plans: dict[tuple[str, ...], PosePlan]
    prim_pose: Callable[[str], Pose]

    # -- bodies ----------------------------------------------------------------------------------
    def _body(self, prim_path: str) -> BodyHandle:
        handle = self.scene.bodies.get(prim_path)
        if handle is not None:
            return handle
        owner = self._collider_owner(prim_path)
        if owner is not None:
            return self.scene.bodies[owner]
        raise WorldError(f"{prim_path} is not a rigid body or collider of this stage")

    def body_handle(self, prim_path: str) -> BodyHandle | None:
        """The built body that simulates a body or collider prim, or None."""
        try:
            return self._body(prim_path)
        except WorldError:
            return None

    def body_of(self, prim_path: str) -> str | None:
        handle = self.body_handle(prim_path)
        return None if handle is None else handle.path

    def same_body(self, path_a: str, path_b: str) -> bool:
        if path_a == path_b:
            return True
        body = self.body_of(path_a)
        return body is not None and body == self.body_of(path_b)

    def body_link(self, prim_path: str) -> tuple[int, int]:
        """(PyBullet body id, link index) of a body prim or of a collider under it."""
        handle = self._body(prim_path)
        return handle.body_id, handle.link

    def inertial_in_prim(self, prim_path: str) -> Pose:
        """The link's inertial (centre-of-mass) frame in the prim frame: PyBullet constraint frames are relative to it."""
        return self._body(prim_path).inertial_in_prim

    def prim_at(self, body_id: int, link_index: int) -> str | None:
        return self.scene.by_id.get((body_id, link_index))

    def _collider_owner(self, prim_path: str) -> str | None:
        for body in self.description.bodies.values():
            if any(shape.path == prim_path for shape in body.shapes) and body.path in self.scene.bodies:
                return body.path
        return None

    # -- articulations ---------------------------------------------------------------------------
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
            probe = probe.rsplit("/", 1)[0] if "/" in probe else ""   # a relative path ends here too
        raise WorldError(f"{path} is not part of an articulation")

    # -- poses -----------------------------------------------------------------------------------
    def _inertial_pose(self, handle: BodyHandle) -> Pose:
        if handle.link == -1:
            position, orientation = self.client.getBasePositionAndOrientation(handle.body_id)
        else:
            state = self.client.getLinkState(handle.body_id, handle.link, computeForwardKinematics=1)
            position, orientation = state[0], state[1]
        return tuple(position), tuple(orientation)

    def _body_pose(self, handle: BodyHandle) -> Pose:
        return compose(self._inertial_pose(handle), handle.prim_in_inertial)

    def body_poses(self, paths: Iterable[str]) -> list[Pose]:
        """World poses of rigid-body prims, the same numbers as ``prim_pose`` gives one at a time.

        One ``getLinkStates`` call per multibody instead of a call per link, planned once per
        list of paths: a run report samples every moving body and link, and the per-call cost is
        most of it.
        """
        return self.read_body_poses(paths)()

    def read_body_poses(self, paths: Iterable[str]) -> Callable[[], list[Pose]]:
        """``body_poses`` in two halves: the bodies' states are read now, their prim poses composed when the
        result is called. A recorder captures on every sampled tick and encodes later, so the run pays only
        the read, kept as one array of doubles (7 a body: a long run's reads add nothing for the garbage
        collector to visit)."""
        key = tuple(paths)
        plan = self._pose_plans.get(key)
        if plan is None:
            plan = self._pose_plans[key] = self._pose_plan(key)
        client = self.client
        read = [c for body_id in plan[0] for part in client.getBasePositionAndOrientation(body_id) for c in part]
        for body_id, links in plan[1]:
            states = client.getLinkStates(body_id, links, computeForwardKinematics=1)
            read += [c for state in states for c in state[0] + state[1]]   # a link state begins with its inertial pose
        return partial(_composed_poses, plan, array("d", read))

    def _pose_plan(self, paths: tuple[str, ...]) -> PosePlan:
        """(base body ids, (body id, links) per multibody, each read slot's index in *paths* (bases first, then each
        multibody's links), each slot's prim frame in its inertial frame, each slot's last (inertial position and
        orientation read, as 7 doubles; pose): None until the first)."""
        handles = []
        for path in paths:
            if path not in self.scene.bodies:
                raise WorldError(f"{path} is not a rigid body of this stage")
            handles.append(self.scene.bodies[path])
        order = [index for index, handle in enumerate(handles) if handle.link == -1]
        bases = [handles[index].body_id for index in order]
        grouped: dict[int, list[int]] = {}
        for index, handle in enumerate(handles):
            if handle.link != -1:
                grouped.setdefault(handle.body_id, []).append(index)
        link_groups = []
        for body_id, indices in grouped.items():
            link_groups.append((body_id, [handles[index].link for index in indices]))
            order += indices
        return bases, link_groups, order, [handles[index].prim_in_inertial for index in order], [None] * len(order)

    def _prim_offset(self, prim_path: str) -> tuple[str | None, Pose]:
        """(nearest body ancestor or None, the prim's pose in it), from the stage's authored transforms."""
        if prim_path in self._offsets:
            return self._offsets[prim_path]
        if self.stage is None:
            raise WorldError(f"{prim_path} is not a rigid body of this stage")
        from pxr import Gf

        prim = self.stage.GetPrimAtPath(prim_path)
        if not prim:
            raise WorldError(f"no prim {prim_path} on this stage")
        transform = Gf.Transform(_local_to_world(prim))
        scale = self.description.meters_per_unit
        imaginary = transform.GetRotation().GetQuat().GetImaginary()
        x, y, z = (float(c) * scale for c in transform.GetTranslation())
        world: Pose = ((x, y, z),
                       (imaginary[0], imaginary[1], imaginary[2], transform.GetRotation().GetQuat().GetReal()))
        ancestor = prim.GetParent()
        while ancestor and not ancestor.IsPseudoRoot() and str(ancestor.GetPath()) not in self.scene.bodies:
            ancestor = ancestor.GetParent()
        owner = str(ancestor.GetPath()) if ancestor and not ancestor.IsPseudoRoot() else None
        offset = relative(self.description.bodies[owner].pose, world) if owner else world
        self._offsets[prim_path] = (owner, offset)
        return owner, offset

    def _parent_pose(self, prim_path: str) -> Pose:
        """World pose of the prim's parent (identity at the root or when the parent has no pose)."""
        parent = prim_path.rsplit("/", 1)[0]
        if not parent:
            return IDENTITY_POSE
        try:
            return self.prim_pose(parent)
        except WorldError:
            return IDENTITY_POSE

    def _parent_rotation(self, prim_path: str):
        parent = prim_path.rsplit("/", 1)[0]
        if not parent:
            return (0.0, 0.0, 0.0, 1.0)
        try:
            return self.prim_pose(parent)[1]
        except WorldError:
            return (0.0, 0.0, 0.0, 1.0)


def _local_to_world(prim):
    """The prim's local-to-world matrix, composing the xformOps of every prim on the way, also of prims whose
    type usd-core does not know (Isaac's sensors: OmniLidar, IsaacImuSensor...), which UsdGeom.XformCache takes
    for identities; !resetXformStack! drops what lies above, as USD composes it."""
    from pxr import Gf, UsdGeom

    chain = []
    while prim and not prim.IsPseudoRoot():
        chain.append(prim)
        prim = prim.GetParent()
    matrix = Gf.Matrix4d(1.0)
    for link in reversed(chain):
        xformable = UsdGeom.Xformable(link)
        local = xformable.GetLocalTransformation()
        matrix = local if xformable.GetResetXformStack() else local * matrix
    return matrix


def _composed_poses(plan: PosePlan, read: array) -> list[Pose]:
    """The prim poses of one ``read_body_poses`` read, in its paths' order. A body whose inertial pose is what
    it was at the previous composition (at rest, a fixed base) gets the pose composed then."""
    _bases, _links, order, prim_in_inertial, last = plan
    poses: list = [None] * len(order)
    for slot, index in enumerate(order):
        inertial = read[7 * slot:7 * slot + 7]
        previous = last[slot]
        if previous is None or previous[0] != inertial:
            x, y, z, qx, qy, qz, qw = inertial
            previous = last[slot] = (inertial, compose(((x, y, z), (qx, qy, qz, qw)), prim_in_inertial[slot]))
        poses[index] = previous[1]
    return poses
