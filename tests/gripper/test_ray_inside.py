"""A surface between the attachment joint's origin and its clearance point is gripped: the ray starts
inside the object, and PhysX's scene query reports a hit at distance 0 there (issue 12 item 4a)."""
import pytest
from pxr import Gf, Usd, UsdGeom, UsdPhysics

from graphflow.gripper import manager_for
from graphflow.physics import create_world
from graphflow.usd.resolver import asset_path

GRIPPER = "/ur10/ee_link/SurfaceGripper"
POINT = "/ur10/ee_link/attachment_joint"
CUBE = "/World/Cube"
TIP = (0.163941, 0.688, 0.486)      # the attachment joint's origin at the UR10's default joint state


def ur10_over_cube(clearance, gap):
    """The UR10's suction point *gap* above a 0.1 kg, 50 mm cube on a pedestal; clearanceOffset *clearance*."""
    stage = Usd.Stage.CreateInMemory()
    UsdGeom.SetStageUpAxis(stage, UsdGeom.Tokens.z)
    UsdGeom.SetStageMetersPerUnit(stage, 1.0)
    UsdPhysics.Scene.Define(stage, "/World/physicsScene")
    stage.DefinePrim("/ur10").GetReferences().AddReference(str(asset_path("ur10.usda")))
    stage.GetPrimAtPath(POINT).GetAttribute("isaac:clearanceOffset").Set(clearance)
    top = TIP[2] - gap
    pedestal = UsdGeom.Cube.Define(stage, "/World/Pedestal")
    pedestal.CreateSizeAttr(1.0)
    pedestal.AddTranslateOp().Set(Gf.Vec3d(TIP[0], TIP[1], (top - 0.05) / 2))
    pedestal.AddScaleOp().Set(Gf.Vec3f(0.1, 0.1, top - 0.05))
    UsdPhysics.CollisionAPI.Apply(pedestal.GetPrim())
    cube = UsdGeom.Cube.Define(stage, CUBE)
    cube.CreateSizeAttr(0.05)
    cube.AddTranslateOp().Set(Gf.Vec3d(TIP[0], TIP[1], top - 0.025))
    UsdPhysics.RigidBodyAPI.Apply(cube.GetPrim())
    UsdPhysics.CollisionAPI.Apply(cube.GetPrim())
    UsdPhysics.MassAPI.Apply(cube.GetPrim()).CreateMassAttr(0.1)
    return create_world(stage)


@pytest.mark.parametrize("gap, grips", [(0.005, True), (0.012, False)])
def test_a_cube_between_the_joint_origin_and_the_clearance_point_is_gripped(gap, grips):
    """clearanceOffset 8 mm, maxGripDistance 10 mm. The cube's top 5 mm below the joint origin: the ray
    starts 3 mm inside the cube and grips it (before: PyBullet's ray from inside saw nothing, never
    gripped). 12 mm below: out of the ray's reach, not gripped. A close never moves the cube."""
    with ur10_over_cube(0.008, gap) as world:
        manager = manager_for(world)
        for _ in range(3):
            world.step()
        before = world.prim_pose(CUBE)[0]
        manager.set_gripper_action(GRIPPER, 1.0)
        for _ in range(3):
            world.step()
        assert manager.get_gripped_objects(GRIPPER) == ([CUBE] if grips else [])
        assert world.prim_pose(CUBE)[0] == pytest.approx(before, abs=2e-4)       # a close does not push the cube
