"""Isaac Sim's surface-gripper gantry stage, prepared in memory as Isaac's own tests do.

The shared file is never written: an in-memory stage references it at
``/World`` and the grippers (and, for the two-gripper test, a second carriage)
are authored on the in-memory root layer.
"""

import pytest
from conftest import ISAAC_GANTRY

from graphflow.gripper.usd_schema import define_surface_gripper, register_schema

GRIPPER = "/World/SurfaceGripper"
SECOND_GRIPPER = "/World/SurfaceGripper_01"
FRAMES_PER_SECOND = 60


def isaac_gantry_stage(second_gripper_over: str | None = None):
    """The gantry referenced at /World with /World/SurfaceGripper on the nine cone joints.

    The shared file is the interactive example's copy, which lacks the test
    copy's second carriage. With *second_gripper_over* (a box path) a second
    cone gripper is cloned in memory (``Gripper_Cones_01`` with
    ``Surface_Gripper_Joints_01``) and welded to the world over that box, at
    the height the gantry reaches at ``z_joint = 0.140`` (cone centres 9.9 mm
    above the top layer); ``/World/SurfaceGripper_01`` uses it.
    """
    if not ISAAC_GANTRY.is_file():
        pytest.skip(f"{ISAAC_GANTRY} is not available")
    register_schema()
    from pxr import Usd, UsdGeom

    stage = Usd.Stage.CreateInMemory()
    UsdGeom.SetStageUpAxis(stage, UsdGeom.Tokens.z)
    UsdGeom.SetStageMetersPerUnit(stage, 1.0)
    stage.DefinePrim("/World", "Xform").GetReferences().AddReference(str(ISAAC_GANTRY))
    _gripper(stage, GRIPPER, "/World/Surface_Gripper_Joints")
    if second_gripper_over is not None:
        _clone_cones(stage, second_gripper_over)
        _gripper(stage, SECOND_GRIPPER, "/World/Surface_Gripper_Joints_01")
    return stage


def _gripper(stage, path, joints_scope):
    prim = define_surface_gripper(stage, path)
    prim.GetRelationship("isaac:attachmentPoints").SetTargets(
        [child.GetPath() for child in stage.GetPrimAtPath(joints_scope).GetChildren()])


CONE_CENTRE_HEIGHT_AT_0140 = 1.5 - 0.140 - 0.15007496


def _clone_cones(stage, box_path):
    from pxr import Gf, Sdf, Usd, UsdGeom, UsdPhysics

    source = Sdf.Layer.FindOrOpen(str(ISAAC_GANTRY))
    root = stage.GetRootLayer()
    for name in ("Gripper_Cones", "Surface_Gripper_Joints"):
        Sdf.CreatePrimInLayer(root, f"/World/{name}_01")
        Sdf.CopySpec(source, f"/World/{name}", root, f"/World/{name}_01")
    box = UsdGeom.Xformable(stage.GetPrimAtPath(box_path)).ComputeLocalToWorldTransform(Usd.TimeCode.Default())
    position = Gf.Vec3d(box.ExtractTranslation()[0], box.ExtractTranslation()[1], CONE_CENTRE_HEIGHT_AT_0140)
    cones = stage.GetPrimAtPath("/World/Gripper_Cones_01")
    cones.GetAttribute("xformOp:translate").Set(position)
    cones.GetAttribute("xformOp:orient").Set(Gf.Quatd(1.0))
    cones.CreateAttribute("physxRigidBody:disableGravity", Sdf.ValueTypeNames.Bool).Set(True)
    anchor = UsdPhysics.FixedJoint.Define(stage, "/World/Gripper_Cones_01/Anchor")
    anchor.CreateBody1Rel().SetTargets([cones.GetPath()])
    anchor.CreateLocalPos0Attr(Gf.Vec3f(position))
    for joint in stage.GetPrimAtPath("/World/Surface_Gripper_Joints_01").GetChildren():
        joint.GetRelationship("physics:body0").SetTargets([cones.GetPath()])
        joint.GetRelationship("physics:body1").ClearTargets(True)


class GantryDriver:
    """Isaac's ``update_joint_target_positions`` and frame stepping, on a graphflow world."""

    def __init__(self, world, manager):
        self.world = world
        self.manager = manager

    def frames(self, count):
        for _ in range(count):
            self.world.step()

    def move(self, x, y, z, settle=60):
        """Write the three drive targets, one frame each, then *settle* frames (Isaac's helper)."""
        for axis, value in (("x", x), ("y", y), ("z", z)):
            self.world.set_attribute(f"/World/Joints/{axis}_joint", "drive:linear:physics:targetPosition", value)
            self.frames(1)
        self.frames(settle)

    def action(self, value, frames, paths=(GRIPPER,)):
        self.manager.set_gripper_action_batch(list(paths), [value] * len(paths))
        self.frames(frames)

    def status(self, path=GRIPPER):
        return self.manager.get_gripper_status(path).token

    def gripped(self, path=GRIPPER):
        return self.manager.get_gripped_objects(path)
