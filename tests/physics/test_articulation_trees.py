"""Articulations that are trees: branches, joints authored child-to-parent, floating bases, the krabby hexapod."""
import math

import pytest
from conftest import USDA_SAMPLES as SAMPLES
from pxr import Gf, Usd, UsdGeom, UsdPhysics, UsdShade

from graphflow.physics import create_world
from graphflow.poses import compose, quat_from_axis_angle, relative

KRABBY = SAMPLES / "krabby_crab_simple.usda"


def make_stage():
    stage = Usd.Stage.CreateInMemory()
    UsdGeom.SetStageUpAxis(stage, UsdGeom.Tokens.z)
    UsdGeom.SetStageMetersPerUnit(stage, 1.0)
    UsdGeom.Xform.Define(stage, "/World")
    scene = UsdPhysics.Scene.Define(stage, "/World/PhysicsScene")
    scene.CreateGravityDirectionAttr(Gf.Vec3f(0, 0, -1))
    scene.CreateGravityMagnitudeAttr(9.81)
    return stage


def add_ground(stage, friction=None):
    plane = UsdGeom.Plane.Define(stage, "/World/Ground")
    plane.CreateAxisAttr("Z")
    UsdPhysics.CollisionAPI.Apply(plane.GetPrim())
    if friction is not None:
        material = UsdShade.Material.Define(stage, "/World/GroundMaterial")
        api = UsdPhysics.MaterialAPI.Apply(material.GetPrim())
        api.CreateStaticFrictionAttr(friction)
        api.CreateDynamicFrictionAttr(friction)
        UsdShade.MaterialBindingAPI.Apply(plane.GetPrim()).Bind(material, UsdShade.Tokens.weakerThanDescendants,
                                                                "physics")


def add_box(stage, path, pose, half_extents, mass, center_of_mass=None):
    """A box body at a world pose ((x, y, z), (qx, qy, qz, qw)) under an untransformed parent."""
    cube = UsdGeom.Cube.Define(stage, path)
    cube.CreateSizeAttr(2.0)
    position, (x, y, z, w) = pose
    cube.AddTranslateOp().Set(Gf.Vec3d(*position))
    cube.AddOrientOp().Set(Gf.Quatf(w, x, y, z))
    cube.AddScaleOp().Set(Gf.Vec3f(*half_extents))
    prim = cube.GetPrim()
    UsdPhysics.RigidBodyAPI.Apply(prim)
    UsdPhysics.CollisionAPI.Apply(prim)
    mass_api = UsdPhysics.MassAPI.Apply(prim)
    mass_api.CreateMassAttr(mass)
    if center_of_mass is not None:    # in the prim's (scaled) frame
        mass_api.CreateCenterOfMassAttr(Gf.Vec3f(*(c / s for c, s in zip(center_of_mass, half_extents))))
    return prim


def add_joint(stage, path, kind, body0, body1, frame, poses, axis="X", limits=None, drive=None):
    """A joint whose frame sits at the world pose *frame* in both bodies (so its coordinate starts at 0).

    *poses* maps body paths to their world poses (None = the world). The local positions are given
    in each body's scaled prim frame, as USD wants them.
    """
    joint = {"fixed": UsdPhysics.FixedJoint, "revolute": UsdPhysics.RevoluteJoint,
             "prismatic": UsdPhysics.PrismaticJoint}[kind].Define(stage, path)
    for index, body in ((0, body0), (1, body1)):
        local = relative(poses[body][0], frame) if body is not None else frame
        scale = poses[body][1] if body is not None else (1.0, 1.0, 1.0)
        if body is not None:
            (joint.CreateBody0Rel if index == 0 else joint.CreateBody1Rel)().SetTargets([body])
        x, y, z, w = local[1]
        position = Gf.Vec3f(*(c / s for c, s in zip(local[0], scale)))
        (joint.CreateLocalPos0Attr if index == 0 else joint.CreateLocalPos1Attr)(position)
        (joint.CreateLocalRot0Attr if index == 0 else joint.CreateLocalRot1Attr)(Gf.Quatf(w, x, y, z))
    if kind != "fixed":
        joint.CreateAxisAttr(axis)
        if limits is not None:
            joint.CreateLowerLimitAttr(limits[0])
            joint.CreateUpperLimitAttr(limits[1])
        if drive is not None:
            family = "angular" if kind == "revolute" else "linear"
            api = UsdPhysics.DriveAPI.Apply(joint.GetPrim(), family)
            api.CreateTypeAttr("force")
            api.CreateStiffnessAttr(drive[0])
            api.CreateDampingAttr(drive[1])
            api.CreateTargetPositionAttr(drive[2])
    return joint


TURN_Z = quat_from_axis_angle((0.0, 0.0, 1.0), math.pi / 2)
TILT = quat_from_axis_angle((0.6, 0.0, 0.8), 0.3)
IDENTITY = (0.0, 0.0, 0.0, 1.0)
# the hinge's frame: its Y axis is vertical, so gravity does not load it (a fixed-base drive holds a
# static load L with k M / (M + D), not k: see PyBulletWorld._drive_efforts)
HINGE = compose(((0.0, 0.0, 0.0), quat_from_axis_angle((0.0, 0.0, 1.0), 0.3)),
                ((0.0, 0.0, 0.0), quat_from_axis_angle((1.0, 0.0, 0.0), math.pi / 2)))[1]

# the gantry's situation: a base welded to the world with two prismatic carriages on it, and a
# revolute arm on one carriage; carriage B is authored child-first (body0 = carriage, body1 = base)
TREE_BODIES = {    # path: (world pose, half extents, mass, centre of mass in the body)
    "/Robot/Base": (((0.0, 0.0, 1.0), IDENTITY), (0.5, 0.5, 0.05), 20.0, (0.05, -0.02, 0.0)),
    "/Robot/CarriageA": (((0.3, 0.0, 1.2), IDENTITY), (0.1, 0.1, 0.1), 2.0, (0.0, 0.03, 0.0)),
    "/Robot/CarriageB": (((-0.3, 0.1, 1.2), TURN_Z), (0.1, 0.05, 0.1), 1.5, None),
    "/Robot/Arm": (((0.3, 0.25, 1.1), TILT), (0.03, 0.15, 0.03), 0.5, (0.0, 0.05, 0.0)),
}
TREE_JOINTS = {    # path: (kind, body0, body1, world frame, axis, limits, drive (stiffness, damping, target))
    "/Robot/Joints/Anchor": ("fixed", None, "/Robot/Base", ((0.0, 0.0, 1.0), IDENTITY), "X", None, None),
    "/Robot/Joints/SlideA": ("prismatic", "/Robot/Base", "/Robot/CarriageA", ((0.3, 0.0, 1.1), IDENTITY), "X",
                             (-0.45, 0.45), (2.0e4, 2.0e3, 0.25)),
    "/Robot/Joints/SlideB": ("prismatic", "/Robot/CarriageB", "/Robot/Base", ((-0.3, 0.1, 1.1), TURN_Z), "X",
                             (-0.45, 0.45), (2.0e4, 2.0e3, -0.3)),
    "/Robot/Joints/Hinge": ("revolute", "/Robot/CarriageA", "/Robot/Arm", ((0.3, 0.1, 1.1), HINGE), "Y",
                            (-90.0, 90.0), (500.0, 50.0, 30.0)),
}


def branching_tree_stage():
    stage = make_stage()
    UsdPhysics.ArticulationRootAPI.Apply(UsdGeom.Xform.Define(stage, "/Robot").GetPrim())
    poses = {None: None}
    for path, (pose, half_extents, mass, center_of_mass) in TREE_BODIES.items():
        add_box(stage, path, pose, half_extents, mass, center_of_mass)
        poses[path] = (pose, half_extents)
    for path, (kind, body0, body1, frame, axis, limits, drive) in TREE_JOINTS.items():
        add_joint(stage, path, kind, body0, body1, frame, poses, axis, limits, drive)
    return stage


def distance(a, b):
    return math.dist(a, b)


def angle_between(q, r):
    dot = abs(sum(a * b for a, b in zip(q, r)))
    return 2.0 * math.acos(min(1.0, dot))


def joint_offset(world, path):
    """(translation, rotation) of a joint's body1 frame in its body0 frame, from the simulated body poses."""
    joint = world.description.joints[path]
    frame0 = compose(world.prim_pose(joint.body0), joint.pose0) if joint.body0 else joint.pose0
    frame1 = compose(world.prim_pose(joint.body1), joint.pose1) if joint.body1 else joint.pose1
    return relative(frame0, frame1)


def assert_bodies_follow_the_joints(world, articulation, tolerance=1e-6):
    """Every movable joint's frames differ by exactly its coordinate along (or about) its axis, fixed ones not at all."""
    coordinates = dict(zip(world.joint_paths(articulation), world.joint_positions(articulation)))
    for path, joint in world.description.joints.items():
        if path not in world.scene.articulations[articulation].members:
            continue
        translation, rotation = joint_offset(world, path)
        q = coordinates.get(path, 0.0)
        axis = {"X": (1.0, 0.0, 0.0), "Y": (0.0, 1.0, 0.0), "Z": (0.0, 0.0, 1.0)}[joint.axis]
        expected_translation = tuple(q * a for a in axis) if joint.kind == "prismatic" else (0.0, 0.0, 0.0)
        expected_rotation = quat_from_axis_angle(axis, q) if joint.kind == "revolute" else IDENTITY
        assert distance(translation, expected_translation) < tolerance, path
        assert angle_between(rotation, expected_rotation) < tolerance, path


def test_branching_tree_links_start_at_their_authored_poses():
    with create_world(branching_tree_stage()) as world:
        for path, (pose, *_rest) in TREE_BODIES.items():
            position, orientation = world.prim_pose(path)
            assert distance(position, pose[0]) < 1e-6, path
            assert angle_between(orientation, pose[1]) < 1e-6, path
        assert world.joint_positions("/Robot") == pytest.approx((0.0, 0.0, 0.0), abs=1e-6)


def test_branching_tree_drives_reach_their_targets_inside_the_limits():
    with create_world(branching_tree_stage()) as world:
        paths = world.joint_paths("/Robot")
        for _ in range(60):
            world.step()
        positions = dict(zip(paths, world.joint_positions("/Robot")))
        for path, (kind, _b0, _b1, _frame, _axis, limits, drive) in TREE_JOINTS.items():
            if kind == "fixed":
                continue
            scale = math.pi / 180.0 if kind == "revolute" else 1.0
            assert positions[path] == pytest.approx(drive[2] * scale, abs=1e-3), path
            assert limits[0] * scale <= positions[path] <= limits[1] * scale, path
        assert set(positions) == {"/Robot/Joints/SlideA", "/Robot/Joints/SlideB", "/Robot/Joints/Hinge"}
        assert_bodies_follow_the_joints(world, "/Robot")
        # carriage B's joint runs base -> carriage in the tree but carriage -> base in USD: the
        # carriage moved by -q along the joint's X axis, which the joint frame turns to world Y
        assert distance(world.prim_pose("/Robot/CarriageB")[0], (-0.3, 0.4, 1.2)) < 1e-4
        # the base is welded: it has not moved
        assert distance(world.prim_pose("/Robot/Base")[0], (0.0, 0.0, 1.0)) < 1e-9


# a table standing on four splayed, hinged legs: a floating base (nothing welds it to the world). Like
# the krabby's, its legs are light for their stiff drives and the table's weight loads the hinges: on
# an icy floor (friction 0.05) the feet cannot hold each other the way a stepladder's do.
TABLE_TOP = (0.3, 0.2, 0.025)                   # half extents, m
LEG = (0.02, 0.02, 0.15)
SPLAY = math.radians(25.0)
HINGE_HEIGHT = 0.01 + 2 * LEG[2] * math.cos(SPLAY) + LEG[0] * math.sin(SPLAY)   # feet 1 cm above the ground
TABLE_HEIGHT = HINGE_HEIGHT + TABLE_TOP[2]
CORNERS = {"FL": (0.25, 0.15), "FR": (0.25, -0.15), "RL": (-0.25, 0.15), "RR": (-0.25, -0.15)}


def table_stage():
    stage = make_stage()
    add_ground(stage, friction=0.05)
    UsdPhysics.ArticulationRootAPI.Apply(UsdGeom.Xform.Define(stage, "/Table").GetPrim())
    top = ((0.0, 0.0, TABLE_HEIGHT), IDENTITY)
    add_box(stage, "/Table/Top", top, TABLE_TOP, 20.0)
    poses = {"/Table/Top": (top, TABLE_TOP)}
    for name, (x, y) in CORNERS.items():
        outward = math.copysign(1.0, x)
        tilt = quat_from_axis_angle((0.0, 1.0, 0.0), -outward * SPLAY)      # the foot points away from the top
        centre = (x + outward * LEG[2] * math.sin(SPLAY), y, HINGE_HEIGHT - LEG[2] * math.cos(SPLAY))
        add_box(stage, f"/Table/{name}", (centre, tilt), LEG, 1.0)
        poses[f"/Table/{name}"] = ((centre, tilt), LEG)
        add_joint(stage, f"/Table/Joints/{name}", "revolute", "/Table/Top", f"/Table/{name}",
                  ((x, y, HINGE_HEIGHT), IDENTITY), poses, axis="Y", limits=(-45.0, 45.0),
                  drive=(1.0e4, 1.0e3, 0.0))
    return stage


def test_a_table_on_driven_legs_stands_where_it_was_put():
    with create_world(table_stage()) as world:
        assert not world.scene.articulations["/Table"].fixed_base
        assert world.body_link("/Table/Top")[1] == -1                    # the top is the floating base
        start = world.prim_pose("/Table/Top")[0]
        assert distance(start, (0.0, 0.0, TABLE_HEIGHT)) < 1e-6
        for _ in range(120):
            world.step()
        end = world.prim_pose("/Table/Top")[0]
        assert math.hypot(end[0] - start[0], end[1] - start[1]) < 1e-3   # no drifting away (limit 0.1 m)
        assert end[2] == pytest.approx(TABLE_HEIGHT - 0.01, abs=1e-3)    # dropped 1 cm onto its feet (torque drives: 17 cm)
        assert max(abs(q) for q in world.joint_positions("/Table")) < 1e-3    # 1.1e-4 rad (torque drives: 0.79)
        assert_bodies_follow_the_joints(world, "/Table", tolerance=1e-5)


def test_a_floating_tree_resets_bit_for_bit():
    with create_world(table_stage()) as world:
        def run():
            trace = []
            for _ in range(60):
                world.step()
                trace.append((world.prim_pose("/Table/Top"), world.joint_positions("/Table")))
            return trace
        first = run()
        world.reset()
        assert run() == first


def test_the_krabby_hexapod_stands_on_its_drives():
    """Isaac-authored hexapod: root /krabby (an Xform), 25 bodies, 18 driven revolute joints, 6 fixed feet.

    The feet start 0.18 m above the ground (the fixed joints put each footpad 0.31 m below where it
    is authored), so the crab drops onto them and stands: 0.187 m is the largest displacement
    (a footpad), the drives end within 0.0103 rad (the knees; hips within 0.002).
    """
    if not KRABBY.is_file():
        pytest.skip(f"{KRABBY} is not available")
    from graphflow.physics.stage_report import simulate_report

    report = simulate_report(str(KRABBY), 2.0)
    assert len(report["displacements"]) == 25 and len(report["drive_errors"]) == 18
    assert max(report["displacements"].values()) < 0.2                     # 14.8 m before the fix
    assert report["displacements"]["/krabby/chassis/body"] == pytest.approx(0.181, abs=0.01)
    assert max(report["drive_errors"].values()) < 0.02                     # 3.17 rad before the fix
    with create_world(KRABBY) as world:
        assert world.body_link("/krabby/chassis/body")[1] == -1             # the chassis is the floating base
        assert not world.scene.articulations["/krabby"].fixed_base
