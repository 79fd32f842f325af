"""How a rigid hold and the supports of a resting object share its load (docs/gripper.md, "How the load splits").

A rigid hold and a contact that both hold an object up are statically indeterminate: PyBullet's solver
splits the load however its iterations fall (it held a 5 kg cube 0.05 mm above the table and read its
whole weight, 57.7 N, on the hold); PhysX's contact carries a resting object's weight. So the reading a
rigid hold gives its limits first lets each support plane carry what it can.
"""
from __future__ import annotations

import math

RESTING_GAP = 2.0e-4            # m: a contact this close still supports the held object (resting jitter: 0.05 mm)
SAME_PLANE_COSINE = 0.999       # contact normals this close to parallel are one support plane
SLIDING_SPEED = 0.01            # m/s: contact points faster than this along a support slide (kinetic friction);
                                # a compliantly held cube resting on the table jitters at up to 2.4 mm/s


def supports_relieve(bullet, gripper: tuple[int, int], target: tuple[int, int],
                     force_on_gripper: list[float]) -> list[float]:
    """The hold's force on the gripper once the object's supports carry what they can.

    For each support plane within RESTING_GAP (contacts with the gripper itself left out), the load the
    hold and that plane carry together (the constraint's force plus the contacts' normal and friction
    forces as the solver reported them), less any push of the hold into the plane (which the hold
    keeps), goes to the plane as far as its friction cone allows; the rest stays on the hold. On a plane
    the object slides along, friction is kinetic: the plane carries the normal part and mu N against the
    slide, and the hold the rest (a cup dragging a cube reads the friction it pulls against). Planes are
    served one after the other. Contacts that opened (the object lifted) carry nothing."""
    contacts = [c for c in bullet.getContactPoints(bodyA=target[0], linkIndexA=target[1])
                if c[8] <= RESTING_GAP and (c[2], c[4]) != gripper]
    if not contacts:
        return force_on_gripper
    on_object = [-f for f in force_on_gripper]
    motion = _motion(bullet, *target)
    for normal, group in _planes(contacts):
        support = [0.0, 0.0, 0.0]        # what the solver put on the object through this plane's contacts
        for contact in group:
            for i in range(3):
                support[i] += contact[9] * contact[7][i] - contact[10] * contact[11][i] - contact[12] * contact[13][i]
        # Bullet combines a pair's friction as the product of the two lateral frictions
        friction = bullet.getDynamicsInfo(*target)[1] * bullet.getDynamicsInfo(group[0][2], group[0][4])[1]
        push = min(0.0, _dot(on_object, normal))
        shared = [on_object[i] + support[i] - push * normal[i] for i in range(3)]
        slip = _slip(motion, _motion(bullet, group[0][2], group[0][4]), group, normal)
        speed = math.sqrt(_dot(slip, slip))
        if speed > SLIDING_SPEED:
            pressed = max(0.0, _dot(shared, normal))
            carried = tuple(pressed * normal[i] - friction * pressed * slip[i] / speed for i in range(3))
        else:
            carried = _cone_projection(shared, normal, friction)
        on_object = [push * normal[i] + shared[i] - carried[i] for i in range(3)]
    return [-f for f in on_object]


def _motion(bullet, body: int, link: int) -> tuple:
    """(centre of mass, linear velocity, angular velocity) of a body or link, world frame."""
    if link < 0:
        linear, angular = bullet.getBaseVelocity(body)
        return bullet.getBasePositionAndOrientation(body)[0], linear, angular
    state = bullet.getLinkState(body, link, computeLinkVelocity=1, computeForwardKinematics=1)
    return state[0], state[6], state[7]


def _slip(motion, other, contacts, normal) -> list[float]:
    """The mean velocity of the object's contact points relative to the support's, along the plane."""
    slip = [0.0, 0.0, 0.0]
    for contact in contacts:
        point = contact[5]       # on the object
        mine = _point_velocity(motion, point)
        theirs = _point_velocity(other, point)
        for i in range(3):
            slip[i] += (mine[i] - theirs[i]) / len(contacts)
    along = _dot(slip, normal)
    return [slip[i] - along * normal[i] for i in range(3)]


def _point_velocity(motion, point) -> list[float]:
    centre, linear, angular = motion
    lever = [point[i] - centre[i] for i in range(3)]
    turn = (angular[1] * lever[2] - angular[2] * lever[1], angular[2] * lever[0] - angular[0] * lever[2],
            angular[0] * lever[1] - angular[1] * lever[0])
    return [linear[i] + turn[i] for i in range(3)]


def _planes(contacts) -> list[tuple]:
    """Contacts grouped by support plane: (unit normal into the object, contacts) per normal direction."""
    planes: list[tuple] = []
    for contact in contacts:
        normal = tuple(contact[7])
        for plane_normal, group in planes:
            if _dot(plane_normal, normal) > SAME_PLANE_COSINE:
                group.append(contact)
                break
        else:
            planes.append((normal, [contact]))
    return planes


def _cone_projection(force, normal, friction: float):
    """The nearest force to *force* that a contact with this normal and friction coefficient can exert."""
    along = _dot(force, normal)
    tangential = [force[i] - along * normal[i] for i in range(3)]
    across = math.sqrt(_dot(tangential, tangential))
    if across <= friction * along:
        return tuple(force)
    if friction * across <= -along:
        return 0.0, 0.0, 0.0
    scale = (along + friction * across) / (1.0 + friction * friction)
    return tuple(scale * normal[i] + friction * scale * tangential[i] / across for i in range(3))


def _dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
