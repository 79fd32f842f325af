"""Articulations that are trees: branches, joints authored child-to-parent, floating bases, the krabby hexapod."""
import math
from pathlib import Path

import pytest
from pxr import Gf, Usd, UsdGeom, UsdPhysics

from graphflow.physics import create_world
from graphflow.usd.transforms import compose, quat_from_axis_angle, relative

SAMPLES = Path(__file__).resolve().parents[3] / "shared" / "usda_samples"
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


def add_ground(stage):
    plane = UsdGeom.Plane.Define(stage, "/World/Ground")
    plane.CreateAxisAttr("Z")
    UsdPhysics.CollisionAPI.Apply(plane.GetPrim())


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
