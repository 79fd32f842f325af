"""USD import: one tiny stage per prim kind, checked by the physical numbers it produces."""
import math
import warnings

import pytest
from pxr import Gf, Sdf, Usd, UsdGeom, UsdPhysics, UsdShade

from graphflow.physics import StageError, UnsupportedPrimWarning, create_world
from graphflow.usd.physics_import import load_description


def make_stage(meters_per_unit=1.0):
    stage = Usd.Stage.CreateInMemory()
    UsdGeom.SetStageUpAxis(stage, UsdGeom.Tokens.z)
    UsdGeom.SetStageMetersPerUnit(stage, meters_per_unit)
    UsdGeom.Xform.Define(stage, "/World")
    return stage


def add_body(stage, path, geometry=UsdGeom.Cube, position=(0, 0, 0), scale=None, mass=None, **attributes):
    prim = geometry.Define(stage, path)
    prim.AddTranslateOp().Set(Gf.Vec3d(*position))
    if scale is not None:
        prim.AddScaleOp().Set(Gf.Vec3d(*scale))
    for name, value in attributes.items():
        prim.GetPrim().GetAttribute(name).Set(value)
    UsdPhysics.RigidBodyAPI.Apply(prim.GetPrim())
    UsdPhysics.CollisionAPI.Apply(prim.GetPrim())
    if mass is not None:
        UsdPhysics.MassAPI.Apply(prim.GetPrim()).CreateMassAttr(mass)
    return prim.GetPrim()


def add_ground(stage):
    plane = UsdGeom.Plane.Define(stage, "/World/Ground")
    plane.CreateAxisAttr("Z")
    UsdPhysics.CollisionAPI.Apply(plane.GetPrim())


def settled_height(stage, path, seconds=1.5):
    with create_world(stage) as world:
        for _ in range(int(seconds / world.time_step)):
            world.step()
        return world.prim_pose(path)[0][2]


@pytest.mark.parametrize("geometry, attributes, resting_height", [
    (UsdGeom.Cube, {"size": 0.2}, 0.1),
    (UsdGeom.Sphere, {"radius": 0.1}, 0.1),
    (UsdGeom.Cylinder, {"radius": 0.1, "height": 0.3, "axis": "Z"}, 0.15),
    (UsdGeom.Capsule, {"radius": 0.05, "height": 0.2, "axis": "Z"}, 0.15),
    (UsdGeom.Cone, {"radius": 0.1, "height": 0.2, "axis": "Z"}, 0.1),
])
def test_each_shape_comes_to_rest_on_the_ground_at_its_half_height(geometry, attributes, resting_height):
    stage = make_stage()
    add_ground(stage)
    add_body(stage, "/World/Body", geometry, position=(0, 0, resting_height + 0.05), **attributes)
    assert settled_height(stage, "/World/Body") == pytest.approx(resting_height, abs=0.004)


def test_cylinder_axis_x_lies_on_its_side():
    stage = make_stage()
    add_ground(stage)
    add_body(stage, "/World/Roller", UsdGeom.Cylinder, position=(0, 0, 0.12), radius=0.1, height=0.6, axis="X")
    assert settled_height(stage, "/World/Roller") == pytest.approx(0.1, abs=0.004)


def test_convex_mesh_and_scale():
    stage = make_stage()
    add_ground(stage)
    mesh = UsdGeom.Mesh.Define(stage, "/World/Block")
    points = [(x, y, z) for x in (-0.5, 0.5) for y in (-0.5, 0.5) for z in (-0.5, 0.5)]
    mesh.CreatePointsAttr(points)
    mesh.CreateFaceVertexCountsAttr([4] * 6)
    mesh.CreateFaceVertexIndicesAttr([0, 1, 3, 2, 4, 6, 7, 5, 0, 4, 5, 1, 2, 3, 7, 6, 0, 2, 6, 4, 1, 5, 7, 3])
    mesh.AddTranslateOp().Set(Gf.Vec3d(0, 0, 0.2))
    mesh.AddScaleOp().Set(Gf.Vec3d(0.4, 0.4, 0.1))
    UsdPhysics.RigidBodyAPI.Apply(mesh.GetPrim())
    UsdPhysics.CollisionAPI.Apply(mesh.GetPrim())
    UsdPhysics.MeshCollisionAPI.Apply(mesh.GetPrim()).CreateApproximationAttr("convexHull")
    body = load_description(stage).bodies["/World/Block"]
    assert body.shapes[0].kind == "convex_mesh"
    assert body.mass.mass == pytest.approx(0.4 * 0.4 * 0.1 * 1000.0, rel=1e-5)   # default density 1000 kg/m^3
    assert settled_height(stage, "/World/Block") == pytest.approx(0.05, abs=0.004)


def test_mass_density_and_centre_of_mass():
    stage = make_stage()
    add_body(stage, "/World/Heavy", size=0.1, mass=2.5)
    light = add_body(stage, "/World/Light", size=0.2)
    UsdPhysics.MassAPI.Apply(light).CreateDensityAttr(500.0)
    offset = add_body(stage, "/World/Offset", size=0.1, mass=1.0)
    UsdPhysics.MassAPI(offset).CreateCenterOfMassAttr(Gf.Vec3f(0.02, 0, 0))
    bodies = load_description(stage).bodies
    assert bodies["/World/Heavy"].mass.mass == pytest.approx(2.5)
    assert bodies["/World/Heavy"].mass.diagonal_inertia[0] == pytest.approx(2.5 * 0.1 ** 2 / 6, rel=1e-5)
    assert bodies["/World/Light"].mass.mass == pytest.approx(500.0 * 0.2 ** 3, rel=1e-5)
    assert bodies["/World/Offset"].mass.center_of_mass == pytest.approx((0.02, 0, 0), abs=1e-7)


def test_meters_per_unit_scales_lengths_and_gravity():
    stage = make_stage(meters_per_unit=0.01)
    add_body(stage, "/World/Box", size=10.0, position=(0, 0, 100.0))   # a 0.1 m cube at 1 m
    description = load_description(stage)
    box = description.bodies["/World/Box"]
    assert box.pose[0] == pytest.approx((0, 0, 1.0))
    assert box.shapes[0].half_extents == pytest.approx((0.05, 0.05, 0.05))
    assert box.mass.mass == pytest.approx(1.0, rel=1e-5)                 # 1000 kg/m^3 * 1e-3 m^3
    assert description.gravity == pytest.approx((0, 0, -9.81))


def test_material_friction_decides_whether_a_box_slides_down_a_slope():
    def slide(friction):
        stage = make_stage()
        ramp = UsdGeom.Cube.Define(stage, "/World/Ramp")
        ramp.CreateSizeAttr(1.0)
        ramp.AddRotateYOp().Set(20.0)            # 20 degree slope: tan 20 = 0.36
        ramp.AddScaleOp().Set(Gf.Vec3d(2, 1, 0.1))
        UsdPhysics.CollisionAPI.Apply(ramp.GetPrim())
        material = UsdShade.Material.Define(stage, "/World/Material")
        api = UsdPhysics.MaterialAPI.Apply(material.GetPrim())
        api.CreateStaticFrictionAttr(friction)
        api.CreateDynamicFrictionAttr(friction)
        normal = (math.sin(math.radians(20.0)), 0.0, math.cos(math.radians(20.0)))
        box = add_body(stage, "/World/Box", size=0.1, mass=0.2, position=tuple(0.1005 * c for c in normal))
        UsdGeom.Xformable(box).AddRotateYOp().Set(20.0)            # lying flat on the slope
        for prim in (ramp.GetPrim(), box):
            UsdShade.MaterialBindingAPI.Apply(prim).Bind(material, UsdShade.Tokens.weakerThanDescendants, "physics")
        with create_world(stage) as world:
            start = world.prim_pose("/World/Box")[0]
            for _ in range(60):
                world.step()
            return math.dist(start, world.prim_pose("/World/Box")[0])
    assert slide(0.8) < 0.002
    assert slide(0.1) > 0.1


def test_free_bodies_joined_by_a_fixed_joint_fall_together():
    stage = make_stage()
    add_body(stage, "/World/A", size=0.1, mass=1.0, position=(0, 0, 1.0))
    add_body(stage, "/World/B", size=0.1, mass=1.0, position=(0.3, 0, 1.0))
    joint = UsdPhysics.FixedJoint.Define(stage, "/World/Weld")
    joint.CreateBody0Rel().SetTargets(["/World/A"])
    joint.CreateBody1Rel().SetTargets(["/World/B"])
    joint.CreateLocalPos0Attr(Gf.Vec3f(0.3, 0, 0))
    hinge = UsdPhysics.RevoluteJoint.Define(stage, "/World/Hinge")   # B hangs from the world by a hinge at x = 0.6
    hinge.CreateBody0Rel().SetTargets(["/World/B"])
    hinge.CreateLocalPos0Attr(Gf.Vec3f(0.3, 0, 0))
    hinge.CreateLocalPos1Attr(Gf.Vec3f(0.6, 0, 1.0))
    hinge.CreateAxisAttr("Y")
    with create_world(stage) as world:
        for _ in range(60):
            world.step()
        a, b = world.prim_pose("/World/A")[0], world.prim_pose("/World/B")[0]
        assert math.dist(a, b) == pytest.approx(0.3, abs=3e-3)            # the weld holds (mm stretch at 60 Hz)
        pivot = (0.6, 0.0, 1.0)
        assert math.dist(b, pivot) == pytest.approx(0.3, abs=5e-3)        # the hinge holds B (constraints stretch mm)
        assert a[2] < 0.9                                                 # and the pair swung down
        assert abs(a[1]) < 5e-3 and abs(b[1]) < 5e-3                      # about the Y axis only


def test_articulation_revolute_limits_and_drive():
    stage = make_stage()
    root = UsdGeom.Xform.Define(stage, "/World/Arm")
    UsdPhysics.ArticulationRootAPI.Apply(root.GetPrim())
    add_body(stage, "/World/Arm/base", size=0.1, mass=1.0)
    add_body(stage, "/World/Arm/link", size=0.1, mass=1.0, position=(0.5, 0, 0))
    anchor = UsdPhysics.FixedJoint.Define(stage, "/World/Arm/anchor")
    anchor.CreateBody1Rel().SetTargets(["/World/Arm/base"])
    joint = UsdPhysics.RevoluteJoint.Define(stage, "/World/Arm/hinge")
    joint.CreateBody0Rel().SetTargets(["/World/Arm/base"])
    joint.CreateBody1Rel().SetTargets(["/World/Arm/link"])
    joint.CreateLocalPos1Attr(Gf.Vec3f(-0.5, 0, 0))
    joint.CreateAxisAttr("Z")
    joint.CreateLowerLimitAttr(-30.0)
    joint.CreateUpperLimitAttr(45.0)
    drive = UsdPhysics.DriveAPI.Apply(joint.GetPrim(), "angular")
    drive.CreateStiffnessAttr(50.0)       # N m per degree
    drive.CreateDampingAttr(5.0)
    drive.CreateTargetPositionAttr(30.0)  # degrees
    with create_world(stage) as world:
        assert world.joint_names("/World/Arm") == ("hinge",)
        assert world.get_attribute("/World/Arm/hinge", "physics:upperLimit") == pytest.approx(45.0)
        for _ in range(120):
            world.step()
        assert world.joint_positions("/World/Arm/link")[0] == pytest.approx(math.radians(30.0), abs=1e-4)
        position, _ = world.prim_pose("/World/Arm/link")
        assert position == pytest.approx((0.5 * math.cos(math.radians(30)), 0.5 * math.sin(math.radians(30)), 0),
                                         abs=1e-4)
        world.set_attribute("/World/Arm/hinge", "drive:angular:physics:targetPosition", 80.0)   # beyond the limit
        for _ in range(120):
            world.step()
        assert world.joint_positions("/World/Arm")[0] == pytest.approx(math.radians(45.0), abs=2e-3)


def test_d6_attachment_joints_are_kept_as_descriptions_not_simulated():
    stage = make_stage()
    add_body(stage, "/World/Tool", size=0.1, mass=1.0, position=(0, 0, 1.0))
    joint = UsdPhysics.Joint.Define(stage, "/World/Tool/attachment")
    joint.CreateBody0Rel().SetTargets(["/World/Tool"])
    joint.CreateLocalPos0Attr(Gf.Vec3f(0, 0, -0.05))
    joint.CreateLocalRot0Attr(Gf.Quatf(0, 1, 0, 0))
    joint.CreateExcludeFromArticulationAttr(True)
    UsdPhysics.LimitAPI.Apply(joint.GetPrim(), "rotX").CreateLowAttr(-3.0)
    UsdPhysics.LimitAPI(joint.GetPrim(), "rotX").CreateHighAttr(3.0)
    UsdPhysics.LimitAPI.Apply(joint.GetPrim(), "transX").CreateLowAttr(1.0)
    UsdPhysics.LimitAPI(joint.GetPrim(), "transX").CreateHighAttr(-1.0)
    UsdPhysics.DriveAPI.Apply(joint.GetPrim(), "transZ").CreateStiffnessAttr(5000.0)
    with create_world(stage) as world:
        attachment = world.attachment_joints["/World/Tool/attachment"]
        assert attachment.body0 == "/World/Tool" and attachment.body1 is None
        assert attachment.pose0[0] == pytest.approx((0, 0, -0.05))
        assert attachment.pose0[1] == pytest.approx((1, 0, 0, 0), abs=1e-7)      # xyzw: USD's (0, 1, 0, 0)
        assert attachment.limits["rotX"].high == pytest.approx(math.radians(3.0))
        assert attachment.limits["transX"].locked
        assert attachment.drives["transZ"].stiffness == pytest.approx(5000.0)
        for _ in range(30):
            world.step()
        assert world.prim_pose("/World/Tool")[0][2] < 0.9      # not held by the unbuilt joint: it falls


def test_unsupported_prims_warn_once_with_their_path():
    stage = make_stage()
    add_body(stage, "/World/A", size=0.1, mass=1.0)
    add_body(stage, "/World/B", size=0.1, mass=1.0, position=(1, 0, 0))
    joint = UsdPhysics.DistanceJoint.Define(stage, "/World/Rope")
    joint.CreateBody0Rel().SetTargets(["/World/A"])
    joint.CreateBody1Rel().SetTargets(["/World/B"])
    with pytest.warns(UnsupportedPrimWarning, match="/World/Rope"):
        description = load_description(stage)
    assert [path for path, _ in description.unsupported] == ["/World/Rope"]


def test_an_authored_sleep_threshold_is_named_not_dropped():
    """PhysX would let the body sleep; graphflow keeps every body awake and says so, once per body."""
    stage = make_stage()
    add_body(stage, "/World/Box", size=0.1, mass=1.0, position=(0, 0, 1.0))
    add_body(stage, "/World/Other", size=0.1, mass=1.0, position=(1, 0, 1.0))
    stage.GetPrimAtPath("/World/Box").CreateAttribute("physxRigidBody:sleepThreshold", Sdf.ValueTypeNames.Float).Set(0.5)
    with pytest.warns(UnsupportedPrimWarning, match="/World/Box"):
        description = load_description(stage)
    assert description.unsupported == [("/World/Box", "physxRigidBody:sleepThreshold is not simulated: "
                                                      "bodies never sleep")]


def test_prims_the_build_leaves_out_warn_once_and_leave_the_parsed_stage_untouched():
    stage = make_stage()
    add_body(stage, "/World/Tool", size=0.1, mass=1.0, position=(0, 0, 1.0))
    joint = UsdPhysics.Joint.Define(stage, "/World/Tool/loose")      # a D6 the gripper does not own
    joint.CreateBody0Rel().SetTargets(["/World/Tool"])
    description = load_description(stage)
    with pytest.warns(UnsupportedPrimWarning, match="/World/Tool/loose"):
        world = create_world(stage)
    with world:
        assert ("/World/Tool/loose", "a D6 joint that is not a surface-gripper attachment point") in world.unsupported
        assert world.description.unsupported == description.unsupported == []
        with warnings.catch_warnings():
            warnings.simplefilter("error")
            world.reset()                                            # the same build: no second warning
        assert len(world.unsupported) == 1


def test_drive_targets_are_run_time_state_restored_by_reset():
    stage = make_stage()
    add_body(stage, "/World/Base", size=0.1, mass=1.0)
    add_body(stage, "/World/Slider", size=0.1, mass=1.0, position=(0, 0, 0.2))
    UsdPhysics.ArticulationRootAPI.Apply(stage.GetPrimAtPath("/World"))
    fixed = UsdPhysics.FixedJoint.Define(stage, "/World/anchor")
    fixed.CreateBody1Rel().SetTargets(["/World/Base"])
    joint = UsdPhysics.PrismaticJoint.Define(stage, "/World/slide")
    joint.CreateAxisAttr("Z")
    joint.CreateBody0Rel().SetTargets(["/World/Base"])
    joint.CreateBody1Rel().SetTargets(["/World/Slider"])
    joint.CreateLocalPos0Attr(Gf.Vec3f(0, 0, 0.2))
    drive = UsdPhysics.DriveAPI.Apply(joint.GetPrim(), "linear")
    drive.CreateStiffnessAttr(1000.0)
    drive.CreateDampingAttr(100.0)
    drive.CreateTargetPositionAttr(0.05)
    with create_world(stage) as world:
        name = "drive:linear:physics:targetPosition"
        assert world.get_attribute("/World/slide", name) == pytest.approx(0.05)
        world.set_joint_targets("/World", [0], positions=[0.1])
        assert world.get_attribute("/World/slide", name) == pytest.approx(0.1)
        assert world.description.joints["/World/slide"].drive.target_position == pytest.approx(0.05)
        world.reset()
        assert world.get_attribute("/World/slide", name) == pytest.approx(0.05)


def test_missing_file_is_a_one_line_stage_error(tmp_path):
    with pytest.raises(StageError, match=r"nothing\.usda: no such stage file") as caught:
        create_world(tmp_path / "nothing.usda")
    assert "\n" not in str(caught.value)


def test_a_file_that_is_not_usd_is_a_one_line_stage_error(tmp_path):
    path = tmp_path / "notes.usda"
    path.write_text("these are notes, not a stage\n")
    with pytest.raises(StageError, match="notes.usda: not a USD stage") as caught:
        create_world(path)
    assert "\n" not in str(caught.value)
    assert isinstance(caught.value, ValueError)


def test_a_joint_whose_body_is_missing_names_file_and_prims(tmp_path):
    stage = make_stage()
    add_body(stage, "/World/Box", size=0.1, mass=1.0)
    joint = UsdPhysics.RevoluteJoint.Define(stage, "/World/Hinge")
    joint.CreateBody0Rel().SetTargets(["/World/Gone"])
    joint.CreateBody1Rel().SetTargets(["/World/Box"])
    path = tmp_path / "broken.usda"
    stage.GetRootLayer().Export(str(path))
    with pytest.raises(StageError, match=r"broken\.usda: joint /World/Hinge: body0 </World/Gone> does not exist"):
        create_world(path)


def test_a_frame_body_without_mass_or_colliders_gets_a_small_spheres_inertia_on_identity_axes():
    """A site (RigidBodyAPI only): usd-core returns a negative mass and leaves the principal axes uninitialised
    (values like (1.2e29, 4.6e-41, 1.0e9, ...), different from call to call), which once diverged a UR5e carrying
    such a site at its first step. A 1 g sphere's inertia is the same about every axis: identity axes."""
    stage = make_stage()
    sites = []
    for index in range(20):        # many frames: each call leaves different garbage behind it
        site = UsdGeom.Xform.Define(stage, f"/World/Site{index}")
        UsdPhysics.RigidBodyAPI.Apply(site.GetPrim())
        sites.append(f"/World/Site{index}")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", UnsupportedPrimWarning)
        bodies = load_description(stage).bodies
    for path in sites:
        properties = bodies[path].mass
        assert properties.mass == pytest.approx(0.001)
        assert properties.diagonal_inertia == pytest.approx((0.4 * 0.001 * 0.01 ** 2,) * 3)
        assert properties.principal_axes == (0.0, 0.0, 0.0, 1.0)


def test_a_body_without_enabled_colliders_gets_its_geometry_inertia():
    """usd-core warns "possibly invalid inertia tensor of {1,1,1}" for these, uses a small sphere and leaves
    the principal axes uninitialised (different in every process: the krabby's femurs and tibias)."""
    stage = make_stage()
    femur = add_body(stage, "/World/Femur", position=(0, 0, 1), scale=(0.02, 0.45, 0.05), mass=2.8, size=1.0)
    femur.GetAttribute("physics:collisionEnabled").Set(False)
    tibia = UsdGeom.Cube.Define(stage, "/World/Tibia")            # a rigid body with no collider at all
    tibia.CreateSizeAttr(1.0)
    tibia.AddScaleOp().Set(Gf.Vec3d(0.02, 0.051, 0.8128))
    UsdPhysics.RigidBodyAPI.Apply(tibia.GetPrim())
    UsdPhysics.MassAPI.Apply(tibia.GetPrim()).CreateMassAttr(0.72)
    bodies = load_description(stage).bodies

    def box(mass, x, y, z):           # full edge lengths
        return [mass * (y * y + z * z) / 12, mass * (x * x + z * z) / 12, mass * (x * x + y * y) / 12]

    for path, mass, size in (("/World/Femur", 2.8, (0.02, 0.45, 0.05)), ("/World/Tibia", 0.72, (0.02, 0.051, 0.8128))):
        properties = bodies[path].mass
        assert properties.mass == pytest.approx(mass)
        assert sorted(properties.diagonal_inertia) == pytest.approx(sorted(box(mass, *size)), rel=1e-6)
        # the principal axes carry each principal moment onto the body axis it belongs to
        from graphflow.poses import quat_rotate
        for moment, axis in zip(properties.diagonal_inertia, ((1, 0, 0), (0, 1, 0), (0, 0, 1))):
            direction = [abs(c) for c in quat_rotate(properties.principal_axes, axis)]
            assert moment == pytest.approx(box(mass, *size)[direction.index(max(direction))], rel=1e-6)
