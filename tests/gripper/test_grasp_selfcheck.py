"""Isaac's standalone self-check ``gripper_grasp.py`` (reference §7.4), with USD write-back on."""
import pytest

from graphflow.gripper import create_surface_gripper, manager_for, register_schema
from graphflow.gripper.view import GripperView
from graphflow.physics import create_world

CARRIER_Z = 0.40
JOINT = "/World/Joints/lift"
TARGET = "/World/Target"


def _grasp_stage():
    register_schema()
    from pxr import Gf, Sdf, Usd, UsdGeom, UsdPhysics

    stage = Usd.Stage.CreateInMemory()
    UsdGeom.SetStageUpAxis(stage, UsdGeom.Tokens.z)
    UsdGeom.SetStageMetersPerUnit(stage, 1.0)
    UsdPhysics.Scene.Define(stage, "/World/physicsScene")
    ground = UsdGeom.Plane.Define(stage, "/World/Ground")
    ground.CreateAxisAttr("Z")
    UsdPhysics.CollisionAPI.Apply(ground.GetPrim())

    def cube(path, z, mass):
        shape = UsdGeom.Cube.Define(stage, path)
        shape.CreateSizeAttr(0.04)          # size, not a scale op, as the example insists
        shape.AddTranslateOp().Set(Gf.Vec3d(0, 0, z))
        UsdPhysics.RigidBodyAPI.Apply(shape.GetPrim())
        UsdPhysics.CollisionAPI.Apply(shape.GetPrim())
        UsdPhysics.MassAPI.Apply(shape.GetPrim()).CreateMassAttr(mass)
        return shape.GetPrim()

    # Isaac's carrier is a kinematic body; here it is an articulation root welded to the world (as the
    # gantry's Claw_base), since graphflow drives joints of articulations
    carrier = cube("/World/Carrier", CARRIER_Z, mass=0.05)
    UsdPhysics.ArticulationRootAPI.Apply(carrier)
    anchor = UsdPhysics.FixedJoint.Define(stage, "/World/Carrier/Anchor")
    anchor.CreateBody1Rel().SetTargets([carrier.GetPath()])
    anchor.CreateLocalPos0Attr(Gf.Vec3f(0, 0, CARRIER_Z))
    gripper = cube("/World/Gripper", 0.20, mass=0.05)
    gripper.CreateAttribute("physxRigidBody:disableGravity", Sdf.ValueTypeNames.Bool).Set(True)
    cube(TARGET, 0.02, mass=0.05)

    lift = UsdPhysics.PrismaticJoint.Define(stage, JOINT)
    lift.CreateAxisAttr("Z")
    lift.CreateBody0Rel().SetTargets([Sdf.Path("/World/Carrier")])
    lift.CreateBody1Rel().SetTargets([Sdf.Path("/World/Gripper")])
    lift.CreateLowerLimitAttr(-1.0)
    lift.CreateUpperLimitAttr(1.0)
    drive = UsdPhysics.DriveAPI.Apply(lift.GetPrim(), "linear")
    drive.CreateTypeAttr("force")
    drive.CreateStiffnessAttr(1e6)
    drive.CreateDampingAttr(1e4)
    drive.CreateMaxForceAttr(1e6)
    drive.CreateTargetPositionAttr(0.20 - CARRIER_Z)

    attach = UsdPhysics.Joint.Define(stage, "/World/Surface_Gripper_Joints/AttachJoint")
    attach.CreateBody0Rel().SetTargets([Sdf.Path("/World/Gripper")])
    attach.CreateBody1Rel().SetTargets([Sdf.Path("/World/Carrier")])
    attach.CreateLocalPos0Attr(Gf.Vec3f(0, 0, -0.02))
    attach.CreateLocalRot0Attr(Gf.Quatf(0, 1, 0, 0))
    attach.CreateExcludeFromArticulationAttr(True)
    for axis in ("transX", "transY", "transZ", "rotX", "rotY", "rotZ"):
        limit = UsdPhysics.LimitAPI.Apply(attach.GetPrim(), axis)
        limit.CreateLowAttr(1.0)
        limit.CreateHighAttr(-1.0)
    from graphflow.gripper import apply_attachment_point_api

    apply_attachment_point_api(attach.GetPrim(), forward_axis="Z", clearance_offset=0.005)
    surface_gripper = create_surface_gripper(stage, "/World")
    surface_gripper.GetRelationship("isaac:attachmentPoints").SetTargets([attach.GetPath()])
    return stage, surface_gripper.GetPath().pathString


def test_gripper_grasp_self_check():
    stage, path = _grasp_stage()
    world = create_world(stage)
    try:
        manager = manager_for(world)
        manager.set_write_to_usd(True)
        view = GripperView(manager, [path], max_grip_distance=[0.02], coaxial_force_limit=[100.0],
                           shear_force_limit=[100.0], retry_interval=[1.0])

        def frames(count):
            for _ in range(count):
                world.step()

        def gripper_to(z):
            world.set_attribute(JOINT, "drive:linear:physics:targetPosition", z - CARRIER_Z)

        frames(60)
        assert view.get_surface_gripper_status() == ["Open"] and view.get_gripped_objects() == [[]]
        start_z = world.prim_pose(TARGET)[0][2]
        assert start_z == pytest.approx(0.02, abs=1e-3)

        gripper_to(0.065)
        frames(90)
        assert world.prim_pose("/World/Gripper")[0][2] == pytest.approx(0.065, abs=1e-3)   # 5 mm gap
        view.apply_gripper_action([0.5])
        frames(60)
        assert view.get_surface_gripper_status() == ["Closed"] and view.get_gripped_objects() == [[TARGET]]

        for frame in range(1, 31):
            gripper_to(0.065 + (0.30 - 0.065) * frame / 30)
            frames(1)
        frames(60)
        assert world.prim_pose(TARGET)[0][2] - start_z > 0.10
        assert view.get_surface_gripper_status() == ["Closed"]
        # write-back: status and gripped objects on the session sub-layer, not on the root layer
        prim = stage.GetPrimAtPath(path)
        assert prim.GetAttribute("isaac:status").Get() == "Closed"
        assert [str(p) for p in prim.GetRelationship("isaac:grippedObjects").GetTargets()] == [TARGET]
        assert not stage.GetRootLayer().GetAttributeAtPath(f"{path}.isaac:status").HasDefaultValue()

        held_z = world.prim_pose(TARGET)[0][2]
        view.apply_gripper_action([-0.5])
        frames(5)
        assert view.get_surface_gripper_status() == ["Open"] and view.get_gripped_objects() == [[]]
        frames(60)
        assert held_z - world.prim_pose(TARGET)[0][2] > 0.05
        assert prim.GetAttribute("isaac:status").Get() == "Open"
        assert prim.GetRelationship("isaac:grippedObjects").GetTargets() == []

        world.reset()      # the run's USD writes are discarded with the session sub-layer's content
        assert prim.GetAttribute("isaac:status").Get() == "Open"
        assert manager.get_gripper_status(path).token == "Open"
    finally:
        world.close()
