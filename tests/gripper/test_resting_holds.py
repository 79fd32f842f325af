"""A rigid hold on an object the ground still supports does not carry its weight (issue 26 item 2): in PhysX
the contact carries a resting object's weight and nothing pulls along the cup's axis; the attachment takes
the weight once the ground no longer can (the object lifted)."""
import pytest
from pxr import Gf, Sdf, Usd, UsdGeom, UsdPhysics

from graphflow.gripper import manager_for
from graphflow.gripper.usd_schema import create_surface_gripper, register_schema
from graphflow.physics import create_world

CUBE = "/World/Cube"
SLIDE = "/World/Lift/Slide"
G = 9.81


def cup_stage(*, down: bool, cube_mass: float, coaxial_limit: float, gap: float = 0.003, slide_axis: str = "Z"):
    """A cube (0.1 m, *cube_mass*) resting on the ground and a 0.04 m cup on a vertical slide drive (k 1e5 N/m):
    beside the cube facing +X (*down* False) or above it facing -Z, its face *gap* from the cube; one rigid
    attachment point on that face, its forward axis into the cube, the given coaxial limit. *slide_axis* "X":
    the slide moves the cup horizontally instead."""
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
    cup = (0.0, 0.0, 0.1 + gap + 0.02) if down else (-0.05 - gap - 0.02, 0.0, 0.05)
    for path, size, mass, position in (("/World/Lift/Base", 0.1, 1.0, (-0.2, 0, 0.5)),
                                       ("/World/Lift/Cup", 0.04, 0.5, cup),
                                       (CUBE, 0.1, cube_mass, (0.0, 0, 0.05))):
        body = UsdGeom.Cube.Define(stage, path)
        body.CreateSizeAttr(size)
        body.AddTranslateOp().Set(Gf.Vec3d(*position))
        UsdPhysics.RigidBodyAPI.Apply(body.GetPrim())
        UsdPhysics.CollisionAPI.Apply(body.GetPrim())
        UsdPhysics.MassAPI.Apply(body.GetPrim()).CreateMassAttr(mass)
    anchor = UsdPhysics.FixedJoint.Define(stage, "/World/Lift/Anchor")
    anchor.CreateBody1Rel().SetTargets(["/World/Lift/Base"])
    anchor.CreateLocalPos0Attr(Gf.Vec3f(-0.2, 0, 0.5))
    slide = UsdPhysics.PrismaticJoint.Define(stage, SLIDE)
    slide.CreateBody0Rel().SetTargets(["/World/Lift/Base"])
    slide.CreateBody1Rel().SetTargets(["/World/Lift/Cup"])
    slide.CreateLocalPos0Attr(Gf.Vec3f(cup[0] + 0.2, 0, cup[2] - 0.5))
    slide.CreateAxisAttr(slide_axis)
    drive = UsdPhysics.DriveAPI.Apply(slide.GetPrim(), "linear")
    drive.CreateStiffnessAttr(1e5)
    drive.CreateDampingAttr(2e3)
    drive.CreateTargetPositionAttr(0.0)
    point = UsdPhysics.Joint.Define(stage, "/World/Lift/Cup/Suction")
    point.CreateBody0Rel().SetTargets([Sdf.Path("/World/Lift/Cup")])
    if down:     # the joint's X turned to -Z: a quarter turn about Y
        point.CreateLocalPos0Attr(Gf.Vec3f(0, 0, -0.02))
        point.CreateLocalRot0Attr(Gf.Quatf(0.70710678, 0, 0.70710678, 0))
    else:
        point.CreateLocalPos0Attr(Gf.Vec3f(0.02, 0, 0))
    point.CreateExcludeFromArticulationAttr(True)
    for axis in ("transX", "transY", "transZ", "rotX", "rotY", "rotZ"):
        limit = UsdPhysics.LimitAPI.Apply(point.GetPrim(), axis)
        limit.CreateLowAttr(1.0)
        limit.CreateHighAttr(-1.0)
    point.GetPrim().AddAppliedSchema("IsaacAttachmentPointAPI")
    point.GetPrim().CreateAttribute("isaac:forwardAxis", Sdf.ValueTypeNames.Token, False).Set("X")
    gripper = create_surface_gripper(stage, "/World/Lift/Cup")
    gripper.GetRelationship("isaac:attachmentPoints").SetTargets([point.GetPath()])
    gripper.GetAttribute("isaac:maxGripDistance").Set(0.01)
    gripper.GetAttribute("isaac:coaxialForceLimit").Set(coaxial_limit)
    gripper.GetAttribute("isaac:shearForceLimit").Set(500.0)
    return stage, gripper.GetPath().pathString


def grip_then_lift(stage, gripper, rest_steps=30, lift_steps=120):
    """Settle, close, hold *rest_steps* with the cube on the ground, lift the cup 0.1 m: whether the cube was held
    and its height after each step of the lift, the break reason, and the force read on the hold (N) at the end
    of the rest and of the lift."""
    with create_world(stage) as world:
        manager = manager_for(world)
        for _ in range(10):
            world.step()
        manager.set_gripper_action(gripper, 1.0)
        for _ in range(rest_steps):
            world.step()
            assert manager.get_gripped_objects(gripper) == [CUBE], manager.component(gripper).reason
        forces = [read_force(manager, gripper)]
        world.set_attribute(SLIDE, "drive:linear:physics:targetPosition", 0.1)
        held, heights = [], []
        for _ in range(lift_steps):
            world.step()
            held.append(manager.get_gripped_objects(gripper) == [CUBE])
            heights.append(world.prim_pose(CUBE)[0][2])
        forces.append(read_force(manager, gripper) if held[-1] else None)
        return held, heights, manager.component(gripper).reason, forces


def read_force(manager, gripper) -> float:
    component = manager.component(gripper)
    return component.checked_force(next(iter(component.handles.values())))


def test_a_side_cup_lifts_a_resting_5kg_cube_with_a_1n_coaxial_limit():
    """The weight is shear on a side cup: the cube rises with the cup, 0.1 m less the slide's sag."""
    held, heights, reason, forces = grip_then_lift(*cup_stage(down=False, cube_mass=5.0, coaxial_limit=1.0))
    assert all(held), reason      # broke at rest before: 5.6 N coaxial, the hold carried 57.7 N while resting
    assert forces[0] < 0.5 and forces[1] == pytest.approx(5.0 * G, rel=0.05)
    assert heights[-1] == pytest.approx(0.15 - 5.5 * G / 1e5, abs=3e-3)


def test_a_down_cup_holds_a_resting_1kg_cube_under_a_5n_limit_until_it_is_lifted():
    """1 kg pulls 9.81 N along a down-facing cup's axis once the ground stops carrying it: held while the cube
    rests (the table carries it), broken by a coaxial force near m g as the lift begins."""
    held, heights, reason, _forces = grip_then_lift(*cup_stage(down=True, cube_mass=1.0, coaxial_limit=5.0))
    assert not held[-1] and "coaxial force" in reason, reason
    assert heights[-1] < 0.06


def test_a_down_cup_carries_the_resting_1kg_cube_under_a_20n_limit():
    """Resting, the hold reads ~0 (the table carries the cube); hanging after the lift, the cube's weight."""
    held, heights, reason, forces = grip_then_lift(*cup_stage(down=True, cube_mass=1.0, coaxial_limit=20.0))
    assert all(held), reason
    assert forces[0] < 0.5 and forces[1] == pytest.approx(1.0 * G, rel=0.05)
    assert heights[-1] == pytest.approx(0.15 - 1.5 * G / 1e5, abs=3e-3)


def drag(coaxial_limit, steps=60):
    """Grip a resting 1 kg cube from the side, then pull it along the ground at 0.12 m/s (the slide along X):
    whether it was held after each step of the drag, the reason, and the force read on the hold at the end."""
    stage, gripper = cup_stage(down=False, cube_mass=1.0, coaxial_limit=coaxial_limit, slide_axis="X")
    with create_world(stage) as world:
        manager = manager_for(world)
        for _ in range(10):
            world.step()
        manager.set_gripper_action(gripper, 1.0)
        for _ in range(30):
            world.step()
        assert manager.get_gripped_objects(gripper) == [CUBE] and read_force(manager, gripper) < 0.5
        held = []
        for step in range(steps):
            world.set_attribute(SLIDE, "drive:linear:physics:targetPosition", -0.002 * (step + 1))
            world.step()
            held.append(manager.get_gripped_objects(gripper) == [CUBE])
        force = read_force(manager, gripper) if held[-1] else None
        return held, manager.component(gripper).reason, force


def test_dragging_a_cube_along_the_ground_reads_the_friction_it_pulls_against():
    """Sliding, the ground carries the weight and kinetic friction mu m g against the slide (Bullet's pair
    friction 0.5 x 1 kg x g = 4.905 N), the hold the pull: read 4.905 N to 3 % (the solver's own split put
    5.4 N of the weight on the hold; taking everything the friction cone allows read 0 N)."""
    held, reason, force = drag(10.0)
    assert all(held), reason
    assert force == pytest.approx(0.5 * 1.0 * G, rel=0.03)


def test_a_3n_coaxial_limit_breaks_as_the_drag_begins():
    held, reason, _force = drag(3.0)
    assert not held[-1] and "coaxial force" in reason, reason
