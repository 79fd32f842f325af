"""``graphflow.world.Attachments`` on PyBullet: compliant holds and their force readings.

Isaac attaches a gripped object with the attachment point's own D6 joint, whose
limits and drives make the hold compliant. PyBullet's fixed constraint is
rigid, so a hold here is a ``JOINT_FIXED`` constraint whose *child frame is
moved every step* by a compliance model of the D6:

* The joint's zero is the pose at attach time (Isaac attaches at the current
  relative pose, §2.6); its six coordinates ``x`` (transX..Z along the joint
  frame axes in metres, rotX..Z as a rotation vector in radians) displace the
  object from that pose, and the constraint enforces the displaced pose.
* Each axis is the held object on the D6's spring-damper: ``m x'' = L - k x - c x'``
  (``m`` the object's mass, or for a rotation its inertia about that axis
  through the joint origin), integrated with implicit Euler,
  ``v' = (m v + h (L - k x)) / (m + h c + h^2 k)``, ``x' = x + h v'``, and
  stopped at the axis limits (a locked axis stays 0). Implicit Euler is stable
  for every ``k, c >= 0`` at any step and its equilibrium is exactly
  ``x = L / k``: a held mass sags ``m g / k`` along the axis. With ``k = c = 0``
  the object moves freely between the limits (an axis with neither limit nor
  drive is held rigid instead of letting the object slide away).
* ``L`` is the load on the object that the joint has to carry, measured, not
  guessed: the object's own Newton-Euler balance over the last step minus the
  constraint's wrench (``getConstraintState``, averaged over the step's
  substeps: the last substep's alone let a soft hold ring up) gives gravity,
  contacts and applied forces; the inertia of following the gripper rigidly is subtracted.
  Because the constraint wrench that moves the object cancels out of this
  estimate, moving the frame does not feed back into the load.
* While the held object touches anything (a table, a neighbouring box) each
  axis gets at least ``10 m / h`` of damping: a contact is a far stiffer
  spring than the joint, and its force enters the load explicitly, so with a
  soft, barely damped joint the pair would oscillate (measured: growing
  +-70 mm swings at kd = 1). With that damping one step moves the joint by at
  most a tenth of what the contact asks, so it creeps into place instead: a
  held object pressed onto a table still compresses the joint.
* Several attachment points holding the same object share one constraint and
  one model (their springs act in parallel: stiffnesses and dampings add; the
  axes, origin and limits are those of the first point that attached). Nine
  rigid constraints on one box would fight each other inside the solver and
  report arbitrary internal forces of ~0.1 N per point; one constraint does not.

Forces: ``getConstraintState`` rows 0-2 are the force the constraint applies
to the *parent* (the gripper) in world axes, which is exactly Isaac's
``PxConstraint::getForce`` convention (force on actor0, world frame); the
calibration is asserted in ``tests/gripper/test_attachment.py``. As in PhysX,
where a D6 drive is a soft row, the part along a compliant translation axis
that sits inside its limits is carried by the drive and not reported (Isaac's
gantry example holds 0.2 kg boxes with a 0.005 N coaxial limit on a soft Z
drive, which only works that way); at a limit it is reported. Each point of a
shared hold reports an equal share.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field, replace
from typing import Sequence

import pybullet

from graphflow.physics.support import supports_relieve
from graphflow.poses import (
    AXIS_VECTORS,
    Pose,
    Quat,
    compose,
    invert,
    quat_matrix,
    quat_multiply,
    quat_normalize,
    quat_rotate,
    relative,
)
from graphflow.world import RIGID, AxisCompliance

HOLD_MAX_FORCE = 1.0e7          # N (and N·m); far above any break limit so the reading is never clamped
CONTACT_DAMPING_STEPS = 10      # while the object touches something, damping >= this * m / dt
INSIDE_PROBE_RADIUS = 1.0e-4   # m: a ray starts inside a body when this sphere at its origin is 2 radii deep


@dataclass
class _Hold:
    """One object held by one gripper link: a single constraint shared by every attachment point on it."""

    gripper: tuple[int, int]
    target: tuple[int, int]
    constraint: int
    parent_frame: Pose            # the first point's joint frame in the gripper link's COM frame
    child_at_attach: Pose         # the same frame in the object's COM frame, when attached
    members: dict[int, tuple[AxisCompliance, ...]] = field(default_factory=dict)   # handle -> compliance
    offset: list[float] = field(default_factory=lambda: [0.0] * 6)
    rate: list[float] = field(default_factory=lambda: [0.0] * 6)
    previous: tuple | None = None  # last step's (object v, object w, rigid-follow v, gripper w)
    child: Pose | None = None      # the child frame the constraint enforces now (``child_at_attach`` displaced)
    wrench_sum: list[float] = field(default_factory=lambda: [0.0] * 6)   # the constraint's wrench, summed over
    wrench_count: int = 0                                                # the substeps of the stage step
    axes: tuple[AxisCompliance, ...] = ()   # limits of the first point, summed drives of all
    rigid: bool = True                      # every axis rigid: no compliance model to run (set with ``axes``)

    def combine(self, first: tuple[AxisCompliance, ...]) -> None:
        """Parallel springs: stiffness and damping add up; limits stay the first point's."""
        self.axes = tuple(AxisCompliance(first[i].lower, first[i].upper,
                                         sum(c[i].stiffness for c in self.members.values()),
                                         sum(c[i].damping for c in self.members.values()))
                          for i in range(6))
        self.rigid = all(axis.rigid for axis in self.axes)     # read every substep: derived once here


class PyBulletAttachments:
    """Attachments on one PyBullet client (a ``BulletClient``): attach, detach, comply, read forces."""

    def __init__(self, bullet):
        self.bullet = bullet
        self._holds: dict[tuple, _Hold] = {}
        self._hold_of: dict[int, tuple] = {}
        self._next_handle = 0
        self._inertial: dict[tuple[int, int], tuple] = {}

    # -- poses and velocities (PyBullet constraint frames are relative to COM frames) --

    def _dynamics(self, body: int, link: int):
        key = (body, link)
        if key not in self._inertial:
            info = self.bullet.getDynamicsInfo(body, link)
            self._inertial[key] = (info[0], tuple(info[2]))
        return self._inertial[key]

    def com_pose(self, body: int, link: int) -> Pose:
        if link < 0:
            position, orientation = self.bullet.getBasePositionAndOrientation(body)
        else:
            state = self.bullet.getLinkState(body, link, computeForwardKinematics=1)
            position, orientation = state[0], state[1]
        return tuple(position), tuple(orientation)

    def _hold_frame_rotation(self, hold) -> Quat:
        """The hold's joint frame orientation on the gripper, world axes: ``compose(com_pose, parent_frame)``'s
        rotation, the same numbers without the translation (the force readers ask for it every tick)."""
        body, link = hold.gripper
        if link < 0:
            orientation = self.bullet.getBasePositionAndOrientation(body)[1]
        else:
            orientation = self.bullet.getLinkState(body, link, computeForwardKinematics=1)[1]
        return quat_normalize(quat_multiply(orientation, hold.parent_frame[1]))

    def _com_motion(self, body: int, link: int):
        """(centre-of-mass pose, linear velocity, angular velocity): one PyBullet call for a link."""
        if link < 0:
            position, orientation = self.bullet.getBasePositionAndOrientation(body)
            linear, angular = self.bullet.getBaseVelocity(body)
        else:
            state = self.bullet.getLinkState(body, link, computeLinkVelocity=1, computeForwardKinematics=1)
            position, orientation, linear, angular = state[0], state[1], state[6], state[7]
        return (tuple(position), tuple(orientation)), tuple(linear), tuple(angular)

    def joint_frame(self, body: int, link: int, joint_in_com: Pose) -> Pose:
        """World pose of a joint frame given in the link's centre-of-mass frame."""
        return compose(self.com_pose(body, link), joint_in_com)

    # -- attach / detach --

    def attach(self, gripper: tuple[int, int], joint_in_com: Pose, target: tuple[int, int],
               compliance: tuple[AxisCompliance, ...] = RIGID) -> int:
        """Hold *target* at its current pose relative to a joint frame (given in the gripper link's
        centre-of-mass frame); returns a handle for this attachment point."""
        self._next_handle += 1
        handle = self._next_handle
        key = (gripper, target)
        hold = self._holds.get(key)
        if hold is None:
            frame = self.joint_frame(gripper[0], gripper[1], joint_in_com)
            child = relative(self.com_pose(*target), frame)
            constraint = self.bullet.createConstraint(
                gripper[0], gripper[1], target[0], target[1], pybullet.JOINT_FIXED, [0, 0, 0],
                parentFramePosition=joint_in_com[0], childFramePosition=child[0],
                parentFrameOrientation=joint_in_com[1], childFrameOrientation=child[1])
            self.bullet.changeConstraint(constraint, maxForce=HOLD_MAX_FORCE)
            self._collide(gripper, target, False)
            hold = self._holds[key] = _Hold(gripper, target, constraint, joint_in_com, child)
            first = tuple(compliance)
        else:
            first = next(iter(hold.members.values()))
        hold.members[handle] = tuple(compliance)
        hold.combine(first)
        self._hold_of[handle] = key
        return handle

    def detach(self, handle: int) -> None:
        key = self._hold_of.pop(handle, None)
        if key is None:
            return
        hold = self._holds[key]
        del hold.members[handle]
        if hold.members:
            hold.combine(next(iter(hold.members.values())))
            return
        self.bullet.removeConstraint(hold.constraint)
        del self._holds[key]
        self._collide(hold.gripper, hold.target, True)

    def is_attached(self, handle: int) -> bool:
        return handle in self._hold_of

    def force_on_gripper(self, handle: int, rigid_rows_only: bool = True):
        """This point's share of the force the hold's rigid parts put on the gripper body, world axes, N.

        The constraint's force on its parent is Isaac's ``getForce`` convention
        (force on actor0, world frame). Along a translation axis that is
        compliant and inside its limits the load is carried by the D6 drive,
        not by a rigid row, and is left out (as PhysX reports joint forces);
        on a locked axis it counts, and at a limit the part pressing into it. ``rigid_rows_only=False``
        gives the whole force, drives included. Points holding one object
        share the result equally.
        """
        hold = self._holds[self._hold_of[handle]]
        state = self.bullet.getConstraintState(hold.constraint)
        force = [state[0], state[1], state[2]]
        frame_rotation = None
        for index in range(3 if rigid_rows_only else 0):
            axis, value = hold.axes[index], hold.offset[index]
            if axis.rigid:
                continue
            if frame_rotation is None:
                frame_rotation = self._hold_frame_rotation(hold)
            direction = quat_rotate(frame_rotation, AXIS_VECTORS["XYZ"[index]])
            along = _dot(force, direction)
            # a limit only pushes back: at the lower stop it pulls the gripper towards -axis, at the upper towards +axis
            if (value <= axis.lower and along < 0.0) or (value >= axis.upper and along > 0.0):
                continue
            force = [force[i] - along * direction[i] for i in range(3)]
        if rigid_rows_only:
            force = supports_relieve(self.bullet, hold.gripper, hold.target, force)
        share = 1.0 / len(hold.members)
        return force[0] * share, force[1] * share, force[2] * share

    def torque_on_gripper(self, handle: int):
        """This point's share of the hold's torque on the gripper about the joint origin, world axes, N·m."""
        hold = self._holds[self._hold_of[handle]]
        state = self.bullet.getConstraintState(hold.constraint)
        rotation = self._hold_frame_rotation(hold)
        torque = quat_rotate(rotation, (state[3], state[4], state[5]))
        share = 1.0 / len(hold.members)
        return torque[0] * share, torque[1] * share, torque[2] * share

    def offset(self, handle: int) -> tuple[float, ...]:
        """The hold's joint coordinates (transX..rotZ, m and rad) relative to the attach pose."""
        return tuple(self._holds[self._hold_of[handle]].offset)

    def clear(self) -> None:
        """Forget every hold without touching PyBullet (after the world rebuilt its bodies)."""
        self._holds.clear()
        self._hold_of.clear()
        self._inertial.clear()

    def _collide(self, gripper, target, enabled: bool) -> None:
        self.bullet.setCollisionFilterPair(gripper[0], target[0], gripper[1], target[1], int(enabled))

    # -- compliance, run right after every physics step --

    def after_substep(self) -> None:
        """Add each compliant hold's constraint wrench of this PyBullet step to its stage step's sum.

        The load estimate balances the object's motion over the whole stage step against the
        constraint's wrench; PyBullet reports the wrench of the last substep only, and a soft hold's
        constraint pulls hardest in the first substep after its frame moved: the last substep's
        wrench alone fed back into the load made a 100 N/m, 1 N s/m hold of 1 kg ring up and fling
        the cube metres away at four substeps."""
        for hold in self._holds.values():
            if not hold.rigid:
                state = self.bullet.getConstraintState(hold.constraint)
                total = hold.wrench_sum
                for index in range(6):
                    total[index] += state[index]
                hold.wrench_count += 1

    def update(self, dt: float) -> None:
        """Advance every compliant hold one step (call right after each physics step)."""
        for hold in self._holds.values():
            if not hold.rigid:
                self._advance(hold, dt)

    def _advance(self, hold: _Hold, dt: float) -> None:
        mass, inertia_diagonal = self._dynamics(*hold.target)
        target_com, v_object, w_object = self._com_motion(*hold.target)
        gripper_com, v_gripper, w_gripper = self._com_motion(*hold.gripper)
        lever = _sub(target_com[0], gripper_com[0])
        v_rigid = _add(v_gripper, _cross(w_gripper, lever))
        current = (v_object, w_object, v_rigid, w_gripper)
        previous, hold.previous = hold.previous, current
        state = self._mean_wrench(hold)      # this stage step's: the sum starts again either way
        if previous is None:
            return
        touching = bool(self.bullet.getContactPoints(bodyA=hold.target[0], linkIndexA=hold.target[1]))
        relative_linear = _scale(_sub(_sub(v_object, previous[0]), _sub(v_rigid, previous[2])), 1.0 / dt)
        relative_angular = _scale(_sub(_sub(w_object, previous[1]), _sub(w_gripper, previous[3])), 1.0 / dt)

        # the joint frame in world, at the displaced pose the constraint enforces
        child = hold.child or hold.child_at_attach
        frame = compose(target_com, child)
        force_on_object = (-state[0], -state[1], -state[2])
        pivot_rotation = compose(gripper_com, hold.parent_frame)[1]
        torque_on_object = quat_rotate(pivot_rotation, (-state[3], -state[4], -state[5]))   # about the pivot
        com_lever = _sub(target_com[0], frame[0])
        inertial_force = _scale(relative_linear, mass)
        load_force = _sub(inertial_force, force_on_object)
        angular_inertia = _world_inertia(target_com[1], inertia_diagonal, relative_angular)
        load_torque = _sub(_add(angular_inertia, _cross(com_lever, inertial_force)), torque_on_object)

        rows = quat_matrix(frame[1])
        axes = [(rows[0], rows[3], rows[6]), (rows[1], rows[4], rows[7]), (rows[2], rows[5], rows[8])]
        loads = [_dot(load_force, axis) for axis in axes] + [_dot(load_torque, axis) for axis in axes]
        # about each joint axis through the pivot: the axis in the object's principal frame is the child
        # frame's column, so the object's own part is sum_j I_j c_j^2 (parallel axis theorem for the rest)
        in_body = quat_matrix(child[1])
        ix, iy, iz = inertia_diagonal
        inertias = [mass] * 3 + [ix * in_body[i] * in_body[i] + iy * in_body[3 + i] * in_body[3 + i]
                                 + iz * in_body[6 + i] * in_body[6 + i]
                                 + mass * _dot(_cross(axis, com_lever), _cross(axis, com_lever))
                                 for i, axis in enumerate(axes)]
        for index, axis in enumerate(hold.axes):
            if touching:   # contact forces are stiff springs fed back explicitly: damp the joint enough to creep
                axis = replace(axis, damping=max(axis.damping, CONTACT_DAMPING_STEPS * inertias[index] / dt))
            hold.offset[index], hold.rate[index] = _integrate(
                hold.offset[index], hold.rate[index], loads[index], inertias[index], dt, axis)
        moved = self._displaced_child(hold)
        if moved != child:
            hold.child = moved
            self.bullet.changeConstraint(hold.constraint, jointChildPivot=moved[0],
                                         jointChildFrameOrientation=moved[1], maxForce=HOLD_MAX_FORCE)

    def _mean_wrench(self, hold: _Hold) -> list[float]:
        """The constraint's wrench averaged over the stage step's substeps (then the sum starts again)."""
        if not hold.wrench_count:
            return list(self.bullet.getConstraintState(hold.constraint))
        mean = [total / hold.wrench_count for total in hold.wrench_sum]
        hold.wrench_sum, hold.wrench_count = [0.0] * 6, 0
        return mean

    @staticmethod
    def _displaced_child(hold: _Hold) -> Pose:
        """The child frame that puts the object at the hold's offset ``D`` from the attach pose: ``C D^-1``."""
        if not any(hold.offset):
            return hold.child_at_attach
        offset = hold.offset
        displacement = ((offset[0], offset[1], offset[2]), _quat_from_rotation_vector(offset[3:]))
        return compose(hold.child_at_attach, invert(displacement))


class WorldAttachments:
    """A ``PyBulletWorld``'s ``graphflow.world.Attachments``: prim paths in, one lookup to (body, link), held there.

    Owned by the world: created with it, ``update`` run by ``world.step()`` right
    after the physics step, ``reset`` by ``world.reset()`` (the client's
    constraints are gone with the rebuild).
    """

    def __init__(self, world):
        self.world = world
        self.mechanism = PyBulletAttachments(world.client)
        self._targets: dict[int, str] = {}              # handle -> held body prim
        self._frames_in_com: dict[tuple, Pose] = {}     # (gripper prim, frame in it) -> frame in the link's COM frame

    def _frame_in_com(self, gripper_prim: str, frame: Pose) -> Pose:
        """The frame in the gripper link's centre-of-mass frame (constant until the world is rebuilt)."""
        key = (gripper_prim, frame)
        in_com = self._frames_in_com.get(key)
        if in_com is None:
            in_com = self._frames_in_com[key] = relative(self.world.inertial_in_prim(gripper_prim), frame)
        return in_com

    def frame(self, gripper_prim: str, frame: Pose) -> Pose | None:
        body = self.world.body_handle(gripper_prim)
        if body is None:
            return None
        return self.mechanism.joint_frame(body.body_id, body.link, self._frame_in_com(gripper_prim, frame))

    def attach(self, gripper_prim: str, frame: Pose, target_prim: str,
               compliance: Sequence[AxisCompliance] = RIGID) -> int | None:
        gripper, target = self.world.body_handle(gripper_prim), self.world.body_handle(target_prim)
        if gripper is None or target is None:
            return None
        handle = self.mechanism.attach((gripper.body_id, gripper.link), self._frame_in_com(gripper_prim, frame),
                                       (target.body_id, target.link), compliance)
        self._targets[handle] = target.path
        return handle

    def detach(self, handle: int) -> None:
        self.mechanism.detach(handle)
        self._targets.pop(handle, None)

    def target_of(self, handle: int) -> str:
        return self._targets[handle]

    def force_on_gripper(self, handle: int, rigid_rows_only: bool = True):
        return self.mechanism.force_on_gripper(handle, rigid_rows_only)

    def torque_on_gripper(self, handle: int):
        return self.mechanism.torque_on_gripper(handle)

    def after_substep(self) -> None:
        self.mechanism.after_substep()

    def update(self, dt: float) -> None:
        self.mechanism.update(dt)

    def reset(self) -> None:
        self.mechanism.clear()
        self._targets.clear()
        self._frames_in_com.clear()


def _integrate(value: float, rate: float, load: float, inertia: float, dt: float, axis: AxisCompliance):
    """One implicit-Euler step of ``m x'' = L - k x - c x'`` for one axis, stopped at its limits.

    ``v' = (m v + h (L - k x)) / (m + h c + h^2 k)``, ``x' = x + h v'``: stable for
    every ``k, c >= 0`` and step ``h``, with the equilibrium ``x = L / k``.
    """
    if axis.locked:
        return 0.0, 0.0
    if axis.rigid:
        return value, 0.0
    denominator = inertia + dt * axis.damping + dt * dt * axis.stiffness
    if denominator <= 0.0:
        return value, 0.0
    rate = (inertia * rate + dt * (load - axis.stiffness * value)) / denominator
    value += dt * rate
    if value >= axis.upper:
        value, rate = axis.upper, min(rate, 0.0)
    elif value <= axis.lower:
        value, rate = axis.lower, max(rate, 0.0)
    return value, rate


def _quat_from_rotation_vector(vector: Sequence[float]) -> Quat:
    angle = math.sqrt(sum(c * c for c in vector))
    if angle < 1e-12:
        return 0.0, 0.0, 0.0, 1.0
    s = math.sin(0.5 * angle) / angle
    return vector[0] * s, vector[1] * s, vector[2] * s, math.cos(0.5 * angle)


def _world_inertia(orientation, diagonal, vector):
    """``R diag(I) R^T v``: the world-frame inertia tensor of a body times *v*."""
    local = quat_rotate((-orientation[0], -orientation[1], -orientation[2], orientation[3]), vector)
    return quat_rotate(orientation, tuple(diagonal[i] * local[i] for i in range(3)))


def _add(a, b):
    return a[0] + b[0], a[1] + b[1], a[2] + b[2]


def _sub(a, b):
    return a[0] - b[0], a[1] - b[1], a[2] - b[2]


def _scale(a, s):
    return a[0] * s, a[1] * s, a[2] * s


def _dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def _cross(a, b):
    return a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]
