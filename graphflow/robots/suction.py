"""A suction tool on a link: a cup collider, the surface gripper's D6 attachment joint at its tip, and the
``IsaacSurfaceGripper`` prim, authored as graphflow's UR10 asset has them (same compliance and limits).

The tool points along the link's +Z (the flange axis of URDF arms); the attachment frame's +X, the
gripper's forward axis, is turned onto it, so ``SUCTION_DOWN`` (frame +X down) points the cup down.
"""
from __future__ import annotations

import math

CUP_RADIUS = 0.015            # m
CUP_LENGTH = 0.012            # m, the collider's length below the tip's 'base'
# Frame +X onto the link's +Z: a quarter turn about -Y. (w, x, y, z) as Gf takes it.
X_ONTO_Z = (math.sqrt(0.5), 0.0, -math.sqrt(0.5), 0.0)
# UR10 asset values (graphflow/assets/ur10.usda): 10 mm compliance along the axis, +-5 degrees about it
LIMITS = {"transX": (0.0, 0.01), "transY": (1.0, -1.0), "transZ": (1.0, -1.0),
          "rotX": (-5.0, 5.0), "rotY": (-5.0, 5.0), "rotZ": (-5.0, 5.0)}
DRIVES = {"transX": (1000.0, 100.0), "rotX": (10000.0, 0.0), "rotY": (100.0, 0.0), "rotZ": (100.0, 0.0)}
GRIPPER = {"isaac:maxGripDistance": 0.01, "isaac:coaxialForceLimit": 500.0, "isaac:shearForceLimit": 500.0,
           "isaac:retryInterval": 1.0}


def add_suction_tool(stage, link_path: str, tip: float) -> str:
    """Author the tool on *link_path*, its tip *tip* m along the link's +Z; returns the gripper prim's path."""
    from pxr import Gf, Sdf, UsdGeom, UsdPhysics

    link = stage.GetPrimAtPath(link_path)
    cup = UsdGeom.Cylinder.Define(stage, f"{link_path}/suction_cup")
    cup.CreateAxisAttr("Z")
    cup.CreateRadiusAttr(CUP_RADIUS)
    cup.CreateHeightAttr(CUP_LENGTH)
    cup.AddTranslateOp().Set(Gf.Vec3d(0.0, 0.0, tip - CUP_LENGTH / 2))
    UsdPhysics.CollisionAPI.Apply(cup.GetPrim())
    joint = UsdPhysics.Joint.Define(stage, f"{link_path}/attachment_joint")
    prim = joint.GetPrim()
    prim.SetDocumentation(f"Suction attachment point: the link's +Z, {tip:g} m out; the UR10 tool's compliance")
    for schema in ["IsaacAttachmentPointAPI"] + [f"PhysicsLimitAPI:{axis}" for axis in LIMITS] + [
            f"PhysicsDriveAPI:{axis}" for axis in DRIVES]:
        prim.AddAppliedSchema(schema)
    joint.CreateBody0Rel().SetTargets([link.GetPath()])
    joint.CreateLocalPos0Attr(Gf.Vec3f(0.0, 0.0, tip))
    joint.CreateLocalRot0Attr(Gf.Quatf(*X_ONTO_Z))
    joint.CreateLocalPos1Attr(Gf.Vec3f(0.0, 0.0, 0.0))
    joint.CreateLocalRot1Attr(Gf.Quatf(1.0, 0.0, 0.0, 0.0))
    joint.CreateExcludeFromArticulationAttr(True)
    joint.CreateJointEnabledAttr(True)
    for axis, (low, high) in LIMITS.items():
        prim.CreateAttribute(f"limit:{axis}:physics:low", Sdf.ValueTypeNames.Float).Set(low)
        prim.CreateAttribute(f"limit:{axis}:physics:high", Sdf.ValueTypeNames.Float).Set(high)
    for axis, (stiffness, damping) in DRIVES.items():
        prim.CreateAttribute(f"drive:{axis}:physics:stiffness", Sdf.ValueTypeNames.Float).Set(stiffness)
        if damping:
            prim.CreateAttribute(f"drive:{axis}:physics:damping", Sdf.ValueTypeNames.Float).Set(damping)
    prim.CreateAttribute("isaac:forwardAxis", Sdf.ValueTypeNames.Token, variability=Sdf.VariabilityUniform).Set("X")
    prim.CreateAttribute("isaac:clearanceOffset", Sdf.ValueTypeNames.Float).Set(0.001)
    gripper = stage.DefinePrim(f"{link_path}/SurfaceGripper", "IsaacSurfaceGripper")
    gripper.CreateRelationship("isaac:attachmentPoints").SetTargets([prim.GetPath()])
    gripper.CreateRelationship("isaac:grippedObjects")
    for name, value in GRIPPER.items():
        gripper.CreateAttribute(name, Sdf.ValueTypeNames.Float).Set(value)
    gripper.CreateAttribute("isaac:status", Sdf.ValueTypeNames.Token, variability=Sdf.VariabilityUniform).Set("Open")
    return str(gripper.GetPath())
