"""A cup whose forward axis is horizontal lifts a resting 5 kg cube by its side with a 1 N coaxial limit
authored: the coaxial force is the attachment's load along its axis (here ~0: the weight is shear), not
the contact impulses of the grip and the lift-off (issue 12 item 4b)."""
import pytest
from pxr import Gf, Sdf, Usd, UsdGeom, UsdPhysics

from graphflow.gripper import manager_for
from graphflow.gripper.usd_schema import create_surface_gripper, register_schema
from graphflow.physics import create_world

CUBE = "/World/Cube"
SLIDE = "/World/Lift/Slide"


def side_lift_stage(coaxial_limit, compliant):
    """A 5 kg cube resting on the ground, its side 3 mm from a cup (forward axis +X) on a vertical slide
    drive; the attachment is rigid, or (*compliant*) the UR10's: 10 mm along X on a 1e3 N/m spring,
    +-5 degrees of bending on 100 N m/rad springs."""
    register_schema()
    stage = Usd.Stage.CreateInMemory()
    UsdGeom.SetStageUpAxis(stage, UsdGeom.Tokens.z)
    UsdGeom.SetStageMetersPerUnit(stage, 1.0)
    UsdPhysics.Scene.Define(stage, "/World/PhysicsScene")
    ground = UsdGeom.Cube.Define(stage, "/World/Ground")
    ground.CreateSizeAttr(1.0)
    ground.AddTranslateOp().Set(Gf.Vec3d(0, 0, -0.5))
    ground.AddScaleOp().Set(Gf.Vec3f(4, 4, 1))
    UsdPhysics.CollisionAPI.Apply(ground.GetPrim())
    UsdPhysics.ArticulationRootAPI.Apply(UsdGeom.Xform.Define(stage, "/World/Lift").GetPrim())
    for path, size, mass, position in (("/World/Lift/Base", 0.1, 1.0, (-0.1, 0, 0.5)),
                                       ("/World/Lift/Cup", 0.04, 0.5, (0, 0, 0.05)),
                                       (CUBE, 0.1, 5.0, (0.073, 0, 0.05))):   # cube's side 3 mm from the cup
        cube = UsdGeom.Cube.Define(stage, path)
        cube.CreateSizeAttr(size)
        cube.AddTranslateOp().Set(Gf.Vec3d(*position))
        UsdPhysics.RigidBodyAPI.Apply(cube.GetPrim())
        UsdPhysics.CollisionAPI.Apply(cube.GetPrim())
        UsdPhysics.MassAPI.Apply(cube.GetPrim()).CreateMassAttr(mass)
    anchor = UsdPhysics.FixedJoint.Define(stage, "/World/Lift/Anchor")
    anchor.CreateBody1Rel().SetTargets(["/World/Lift/Base"])
    anchor.CreateLocalPos0Attr(Gf.Vec3f(-0.1, 0, 0.5))
    slide = UsdPhysics.PrismaticJoint.Define(stage, SLIDE)
    slide.CreateBody0Rel().SetTargets(["/World/Lift/Base"])
    slide.CreateBody1Rel().SetTargets(["/World/Lift/Cup"])
    slide.CreateLocalPos0Attr(Gf.Vec3f(0.1, 0, -0.45))
    slide.CreateAxisAttr("Z")
    drive = UsdPhysics.DriveAPI.Apply(slide.GetPrim(), "linear")
    drive.CreateStiffnessAttr(1e5)
    drive.CreateDampingAttr(2e3)
    drive.CreateTargetPositionAttr(0.0)
    point = UsdPhysics.Joint.Define(stage, "/World/Lift/Cup/Suction")
    point.CreateBody0Rel().SetTargets([Sdf.Path("/World/Lift/Cup")])
    point.CreateLocalPos0Attr(Gf.Vec3f(0.02, 0, 0))                      # on the cup's +X face
    point.CreateExcludeFromArticulationAttr(True)
    for axis in ("transX", "transY", "transZ", "rotX", "rotY", "rotZ"):
        limit = UsdPhysics.LimitAPI.Apply(point.GetPrim(), axis)
        low, high = {"transX": (0.0, 0.01), "rotY": (-5.0, 5.0), "rotZ": (-5.0, 5.0)}.get(axis, (1.0, -1.0)) \
            if compliant else (1.0, -1.0)
        limit.CreateLowAttr(low)
        limit.CreateHighAttr(high)
        if compliant and low <= high:
            drive = UsdPhysics.DriveAPI.Apply(point.GetPrim(), axis)
            drive.CreateStiffnessAttr(1e3 if axis == "transX" else 100.0 * 3.14159265 / 180.0)
            drive.CreateDampingAttr(100.0 if axis == "transX" else 1.0 * 3.14159265 / 180.0)
    point.GetPrim().AddAppliedSchema("IsaacAttachmentPointAPI")
    point.GetPrim().CreateAttribute("isaac:forwardAxis", Sdf.ValueTypeNames.Token, False).Set("X")
    gripper = create_surface_gripper(stage, "/World/Lift/Cup")
    gripper.GetRelationship("isaac:attachmentPoints").SetTargets([point.GetPath()])
    gripper.GetAttribute("isaac:maxGripDistance").Set(0.01)
    gripper.GetAttribute("isaac:coaxialForceLimit").Set(coaxial_limit)
    gripper.GetAttribute("isaac:shearForceLimit").Set(500.0)
    return stage, gripper.GetPath().pathString


@pytest.mark.parametrize("compliant", [False, True], ids=["rigid", "compliant"])
def test_a_horizontal_cup_lifts_a_5kg_cube_by_its_side_with_a_1n_coaxial_limit(compliant):
    """Held through the grip, the lift-off and 2 s of lifting; the slide (k = 1e5 N/m) carries cup and
    cube 0.1 m up, less their weight's sag (5.5 kg g / k = 0.54 mm; before issue 12 the drive sagged
    60 mm under it)."""
    stage, gripper = side_lift_stage(1.0, compliant)
    with create_world(stage) as world:
        manager = manager_for(world)
        for _ in range(10):
            world.step()
        manager.set_gripper_action(gripper, 1.0)
        for _ in range(10):
            world.step()
        assert manager.get_gripped_objects(gripper) == [CUBE]
        world.set_attribute(SLIDE, "drive:linear:physics:targetPosition", 0.1)
        for _ in range(120):
            world.step()
            assert manager.get_gripped_objects(gripper) == [CUBE]
        assert world.prim_pose(CUBE)[0][2] == pytest.approx(0.15 - 5.5 * 9.81 / 1e5, abs=3e-3)
