"""Attachment joints as the gripper runtime needs them: body0, joint frame on body0, compliance.

The physics world describes the D6 joints it leaves to the gripper
(``world.attachment_joints``, scale applied, rotations in radians). A joint it
does not list (for instance one not marked ``excludeFromArticulation``, which
Isaac's runtime never checks) is read from USD here with the same conventions.
"""
from __future__ import annotations

import math

from graphflow.gripper.component import AttachmentPoint, compliance_from_joint
from graphflow.gripper.usd_schema import CLEARANCE_OFFSET, read_float, read_forward_axis
from graphflow.world import AXIS_NAMES, AxisCompliance


def attachment_point(stage, joint_path: str, described_joints) -> AttachmentPoint | None:
    """The attachment point for a joint prim, or None when the prim is not a joint with a body0."""
    from pxr import UsdPhysics

    prim = stage.GetPrimAtPath(joint_path)
    if not prim or not prim.IsA(UsdPhysics.Joint):
        return None
    described = _lookup(described_joints, joint_path)
    if described is not None and described.body0:
        body0, pose0 = described.body0, described.pose0
        compliance = compliance_from_joint(described.limits, described.drives)
    else:
        read = _read_joint(stage, prim)
        if read is None:
            return None
        body0, pose0, compliance = read
    return AttachmentPoint(joint_path=joint_path, body0_path=body0, local_pose0=pose0,
                           forward_axis=read_forward_axis(prim),
                           clearance_offset=read_float(prim, CLEARANCE_OFFSET, 0.0),
                           compliance=compliance)


def _lookup(described_joints, path: str):
    if described_joints is None:
        return None
    if isinstance(described_joints, dict):
        return described_joints.get(path)
    return next((joint for joint in described_joints if joint.path == path), None)


def _read_joint(stage, prim):
    from pxr import Usd, UsdGeom, UsdPhysics

    joint = UsdPhysics.Joint(prim)
    targets = joint.GetBody0Rel().GetTargets()
    if not targets:
        return None
    body0 = stage.GetPrimAtPath(targets[0])
    transform = UsdGeom.Xformable(body0).ComputeLocalToWorldTransform(Usd.TimeCode.Default())
    scale = [transform.GetRow3(i).GetLength() for i in range(3)]
    local_position = joint.GetLocalPos0Attr().Get() or (0.0, 0.0, 0.0)
    local_rotation = joint.GetLocalRot0Attr().Get()
    quaternion = ((0.0, 0.0, 0.0, 1.0) if local_rotation is None else
                  (*local_rotation.GetImaginary(), local_rotation.GetReal()))
    pose0 = (tuple(float(local_position[i]) * scale[i] for i in range(3)), tuple(float(c) for c in quaternion))
    return targets[0].pathString, pose0, _read_compliance(prim)


def _read_compliance(prim) -> tuple[AxisCompliance, ...]:
    """Per-axis limits and drives of a D6 (USD degrees and per-degree stiffness turned into radians)."""
    from pxr import UsdPhysics

    axes = []
    for name in AXIS_NAMES:
        to_si = math.radians(1.0) if name.startswith("rot") else 1.0
        lower, upper = float("-inf"), float("inf")
        limit = UsdPhysics.LimitAPI.Get(prim, name)
        if prim.HasAPI(UsdPhysics.LimitAPI, name):
            low, high = limit.GetLowAttr().Get(), limit.GetHighAttr().Get()
            lower = low * to_si if low is not None else lower
            upper = high * to_si if high is not None else upper
        stiffness = damping = 0.0
        if prim.HasAPI(UsdPhysics.DriveAPI, name):
            drive = UsdPhysics.DriveAPI.Get(prim, name)
            stiffness = (drive.GetStiffnessAttr().Get() or 0.0) / to_si
            damping = (drive.GetDampingAttr().Get() or 0.0) / to_si
        axes.append(AxisCompliance(lower, upper, max(0.0, stiffness), max(0.0, damping)))
    return tuple(axes)
