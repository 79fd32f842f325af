"""A UsdPhysics drive on every movable joint: the MJCF actuator's gains where it has a position servo, the
rule's (``gains``) elsewhere; max force from the effort limit; target at the home pose.

A MuJoCo position actuator is ``gainprm = [kp]``, ``biasprm = [0, -kp, -kv]`` with ``biastype affine``
(as ``mujoco-usd-converter`` writes the ``MjcActuator``): force = kp (ctrl - q) - kv v, PhysX's force
drive with stiffness kp and damping kv. kv 0 takes the joint's own damping. Any other actuator
(a motor, one on a tendon) has no such reading and is reported as not mapped.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

from graphflow.robots.gains import Gains, carried_inertia, rule_gains
from graphflow.usd.description import Joint, StageDescription

EFFORT_ATTRIBUTE = "urdf:limit:effort"


@dataclass(frozen=True)
class Servo:
    """An MJCF position actuator read off its ``MjcActuator`` prim."""

    name: str
    joint: str           # joint prim path
    kp: float
    kv: float
    force_limit: float | None


def read_actuators(stage) -> tuple[dict[str, Servo], list[str]]:
    """({joint path: servo}, one line per MjcActuator that is not a position servo on a joint)."""
    servos: dict[str, Servo] = {}
    unmapped: list[str] = []
    for prim in stage.Traverse():
        if prim.GetTypeName() != "MjcActuator":
            continue
        name = prim.GetName()
        targets = prim.GetRelationship("mjc:target").GetTargets() if prim.HasRelationship("mjc:target") else []
        target = stage.GetPrimAtPath(targets[0]) if targets else None
        gain = list(prim.GetAttribute("mjc:gainPrm").Get() or []) if prim.HasAttribute("mjc:gainPrm") else []
        bias = list(prim.GetAttribute("mjc:biasPrm").Get() or []) if prim.HasAttribute("mjc:biasPrm") else []
        bias_type = prim.GetAttribute("mjc:biasType").Get() if prim.HasAttribute("mjc:biasType") else None
        kind = target.GetTypeName() if target is not None else ""
        on_joint = target is not None and kind in ("PhysicsRevoluteJoint", "PhysicsPrismaticJoint")
        kp = gain[0] if gain else 0.0
        if target is not None and on_joint and bias_type == "affine" and kp > 0 and len(bias) >= 3 \
                and math.isclose(bias[1], -kp):
            servos[str(target.GetPath())] = Servo(name, str(target.GetPath()), float(kp), float(-bias[2]),
                                                  _force_limit(prim))
            continue
        what = "on a tendon" if kind == "MjcTendon" else ("not a position servo (no kp)" if on_joint else "on no joint")
        driven = f"{target.GetName()} gets the rule's drive" if target is not None and on_joint else "nothing drives it"
        unmapped.append(f"MjcActuator {prim.GetPath()}: not mapped ({what}); {driven}")
    return servos, unmapped


def _force_limit(prim) -> float | None:
    limited = prim.GetAttribute("mjc:forceLimited").Get() if prim.HasAttribute("mjc:forceLimited") else None
    if limited not in ("true", True) or not prim.HasAttribute("mjc:forceRange:max"):
        return None
    return max(abs(float(prim.GetAttribute("mjc:forceRange:max").Get())),
               abs(float(prim.GetAttribute("mjc:forceRange:min").Get() or 0.0)))


def effort_limit(stage, joint_path: str) -> float | None:
    """The URDF effort limit the converter kept on the joint (N m or N), None if none."""
    attribute = stage.GetPrimAtPath(joint_path).GetAttribute(EFFORT_ATTRIBUTE)
    value = attribute.Get() if attribute and attribute.HasAuthoredValue() else None
    return float(value) if value is not None and value > 0 else None


def plan_gains(stage, description: StageDescription, joints: list[Joint], servos: dict[str, Servo],
               damping: dict[str, float]) -> dict[str, Gains]:
    """The gains of each joint: its servo's, else the rule's with the effort limit as max force."""
    planned = {}
    for joint in joints:
        servo = servos.get(joint.path)
        if servo is not None:
            kv = servo.kv or damping.get(joint.path.rsplit("/", 1)[-1], 0.0)
            planned[joint.path] = Gains(servo.kp, kv, servo.force_limit, f"MjcActuator {servo.name}")
        else:
            planned[joint.path] = rule_gains(carried_inertia(description, joint), effort_limit(stage, joint.path))
    return planned


def author_drives(stage, joints: list[Joint], gains: dict[str, Gains], home: dict[str, float]) -> None:
    """A force drive per joint (``PhysicsDriveAPI:angular`` / ``:linear``) in USD units (degrees for angles)."""
    from pxr import UsdPhysics

    for joint in joints:
        angular = joint.kind == "revolute"
        per_unit = math.pi / 180.0 if angular else 1.0      # USD angular gains are per degree
        chosen = gains[joint.path]
        drive = UsdPhysics.DriveAPI.Apply(stage.GetPrimAtPath(joint.path), "angular" if angular else "linear")
        drive.CreateTypeAttr("force")
        drive.CreateStiffnessAttr(chosen.stiffness * per_unit)
        drive.CreateDampingAttr(chosen.damping * per_unit)
        if chosen.max_force is not None:
            drive.CreateMaxForceAttr(chosen.max_force)
        target = home[joint.path]
        drive.CreateTargetPositionAttr(math.degrees(target) if angular else target)
