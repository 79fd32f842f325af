"""The drive rule: stiffness and damping of a joint the source gives no gains for.

A URDF joint has an effort limit but no gains. graphflow makes each such drive a critically
damped second-order system at one natural frequency, whatever the link: with I the inertia the
joint carries (about its axis, of every body beyond it, at the home pose with the other joints
locked; the carried mass for a prismatic joint),

    k = I w^2,  d = 2 zeta I w,  zeta = 1,  w = 2 pi NATURAL_FREQUENCY,

so that I q'' + d q' + k q = 0 has the double root -w. The frequency is derived from the control
rate: graphs send targets on 60 Hz ticks, and a critically damped step settles to 2 % in
5.83 / w s; NATURAL_FREQUENCY = 10 Hz settles in 0.093 s, within six ticks, so a target sent
on a tick is reached before the motion planner's next phase begins. The effort limit becomes the
drive's max force. Gravity is left to the drive: the static sag of a joint is tau_g / k.

MJCF position actuators carry their own gains (kp, and kv or the joint's damping): those win.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

from graphflow.poses import AXIS_VECTORS, compose, quat_matrix, quat_multiply, quat_rotate
from graphflow.usd.description import Joint, StageDescription

NATURAL_FREQUENCY = 10.0      # Hz
DAMPING_RATIO = 1.0           # critical
SETTLING_FACTOR = 5.83        # 2 % settling time of a critically damped step, in units of 1 / w


@dataclass(frozen=True)
class Gains:
    """SI gains of one drive (per radian or per metre) and where they came from."""

    stiffness: float
    damping: float
    max_force: float | None       # None: the source gives no limit
    source: str                   # "rule" or the MJCF actuator's name


def rule_gains(carried_inertia: float, max_force: float | None) -> Gains:
    """The rule's gains for a joint carrying *carried_inertia* (kg m^2, or kg for a prismatic joint)."""
    omega = 2.0 * math.pi * NATURAL_FREQUENCY
    return Gains(carried_inertia * omega * omega, 2.0 * DAMPING_RATIO * carried_inertia * omega, max_force, "rule")


def carried_inertia(description: StageDescription, joint: Joint) -> float:
    """The inertia the joint moves: about its axis for a revolute joint (kg m^2), the mass for a prismatic one (kg).

    Every body on the joint's far side (body1's side of the kinematic tree) counts, at the poses the
    description holds, with the other joints locked: sum of m |r_perp|^2 + a^T R I R^T a.
    """
    beyond = bodies_beyond(description, joint)
    masses = [(description.bodies[path].pose, description.bodies[path].mass) for path in beyond]
    carried = [(pose, properties) for pose, properties in masses if properties is not None]
    if joint.kind == "prismatic":
        return sum(properties.mass for _pose, properties in carried)
    frame = compose(description.bodies[joint.body0].pose, joint.pose0) if joint.body0 else joint.pose0
    axis = quat_rotate(frame[1], AXIS_VECTORS[joint.axis])
    origin = frame[0]
    total = 0.0
    for pose, properties in carried:
        centre = compose(pose, (properties.center_of_mass, (0.0, 0.0, 0.0, 1.0)))[0]
        r = tuple(c - o for c, o in zip(centre, origin))
        along = sum(a * b for a, b in zip(r, axis))
        total += properties.mass * (sum(c * c for c in r) - along * along)
        principal = quat_matrix(quat_multiply(pose[1], properties.principal_axes))
        for i, moment in enumerate(properties.diagonal_inertia):
            column = sum(principal[3 * row + i] * axis[row] for row in range(3))   # the axis along principal axis i
            total += moment * column * column
    return total


def bodies_beyond(description: StageDescription, joint: Joint) -> list[str]:
    """The bodies the joint moves: body1 and everything joined to it, not crossing back through *joint*."""
    neighbours: dict[str, list[str]] = {}
    for other in description.joints.values():
        if other is joint or other.exclude_from_articulation or other.body0 is None or other.body1 is None:
            continue
        neighbours.setdefault(other.body0, []).append(other.body1)
        neighbours.setdefault(other.body1, []).append(other.body0)
    if joint.body1 is None:
        return []
    seen, pending = {joint.body1}, [joint.body1]
    while pending:
        for nxt in neighbours.get(pending.pop(), []):
            if nxt not in seen and nxt != joint.body0:
                seen.add(nxt)
                pending.append(nxt)
    return sorted(seen)
