"""isaacsim.core.nodes.IsaacComputeTransformTree on the examples of Isaac Sim's own node test
(test_compute_transform_tree.py): each stage Isaac builds (rigid cubes placed at world positions, Xforms, a camera,
name overrides) authored here with pxr, simulated 7 steps at 60 Hz (Isaac's 2 + 5 warm-up updates), and read with
Isaac's tolerances; where the pose is a composition of authored transforms also against that composition."""
import itertools
import math

import pytest

from graphflow.executor import GraphRuntimeError
from graphflow.physics import create_world
from graphflow.testing import NodeHarness

TREE = "isaacsim.core.nodes.IsaacComputeTransformTree"
WARM_UP = 7
STAGE_NUMBERS = itertools.count()


def _stage(tmp_path, prims):
    """A metre, Z-up stage of *prims*: (path, kind, local translation, options); kind "rigid" is Isaac's 1 m,
    1 kg rigid cube with collision, "xform" an Xform, "camera" a Camera, "omnilidar" an OmniLidar. Options:
    orient (w, x, y, z), scale, name (isaac:nameOverride), reset (resetXformStack), schemas (applied API names)."""
    from pxr import Gf, Sdf, Usd, UsdGeom, UsdPhysics

    path = tmp_path / f"tree{next(STAGE_NUMBERS)}.usda"
    stage = Usd.Stage.CreateNew(str(path))
    UsdGeom.SetStageUpAxis(stage, UsdGeom.Tokens.z)
    UsdGeom.SetStageMetersPerUnit(stage, 1.0)
    UsdGeom.Xform.Define(stage, "/World")
    for prim_path, kind, translation, options in prims:
        if kind == "omnilidar":   # the new RTX lidar schema: a typed prim that is no camera
            prim = UsdGeom.Xformable(stage.DefinePrim(prim_path, "OmniLidar"))
        else:
            prim = {"rigid": UsdGeom.Cube, "xform": UsdGeom.Xform, "camera": UsdGeom.Camera}[kind].Define(stage, prim_path)
        for schema in options.get("schemas", ()):
            prim.GetPrim().AddAppliedSchema(schema)
        if options.get("reset"):
            prim.SetResetXformStack(True)
        prim.AddTranslateOp().Set(Gf.Vec3d(*translation))
        if "orient" in options:
            prim.AddOrientOp().Set(Gf.Quatf(*options["orient"]))
        if "scale" in options:
            prim.AddScaleOp().Set(Gf.Vec3f(*options["scale"]))
        if kind == "rigid":
            prim.CreateSizeAttr(1.0)
            UsdPhysics.RigidBodyAPI.Apply(prim.GetPrim())
            UsdPhysics.CollisionAPI.Apply(prim.GetPrim())
            UsdPhysics.MassAPI.Apply(prim.GetPrim()).CreateMassAttr(1.0)
        if "name" in options:
            prim.GetPrim().CreateAttribute("isaac:nameOverride", Sdf.ValueTypeNames.String).Set(options["name"])
    stage.Save()
    return path


def _tree(tmp_path, prims, targets, parent=None):
    """The node's outputs after the warm-up, and the world (closed)."""
    inputs = {"targetPrims": targets, **({"parentPrim": [parent]} if parent else {})}
    with create_world(_stage(tmp_path, prims), time_step=1.0 / 60.0) as world:
        node = NodeHarness(TREE, inputs, world=world)
        for _ in range(WARM_UP):
            world.step()
        return node.compute("execIn").outputs


def _by_child(outputs):
    return {child: (parent, translation, orientation) for parent, child, translation, orientation in zip(
        outputs["parentFrames"], outputs["childFrames"], outputs["translations"], outputs["orientations"])}


FALL = 9.81 * (WARM_UP / 60) ** 2 / 2   # how far a free rigid cube has fallen by then (6.7 cm)


def test_single_rigid_prim_hangs_off_world(tmp_path):
    """Isaac: a rigid cube at (2, 3, 4) is one pair, parent 'world', child 'Cube', translation within 0.1, w ~ 1."""
    outputs = _tree(tmp_path, [("/World/Cube", "rigid", (2, 3, 4), {})], ["/World/Cube"])
    assert outputs["parentFrames"] == ("world",) and outputs["childFrames"] == ("Cube",)
    assert outputs["translations"][0] == pytest.approx((2.0, 3.0, 4.0), abs=0.1)
    assert outputs["translations"][0] == pytest.approx((2.0, 3.0, 4.0 - FALL), abs=0.01)
    assert outputs["orientations"][0][3] == pytest.approx(1.0, abs=0.01)


def test_relative_to_a_parent_prim_and_several_targets(tmp_path):
    """Isaac: a child rigid cube at world x 15 under a rigid parent at 10 reads (5, 0, 0) (within 0.2) relative
    to it; two targets give two pairs, all four outputs of equal length."""
    outputs = _tree(tmp_path, [("/World/Parent", "rigid", (10, 0, 0), {}),
                               ("/World/Parent/Child", "rigid", (5, 0, 0), {})], ["/World/Parent/Child"],
                    parent="/World/Parent")
    assert outputs["parentFrames"] == ("Parent",)
    assert outputs["translations"][0] == pytest.approx((5.0, 0.0, 0.0), abs=0.1)
    both = _tree(tmp_path, [("/World/PrimA", "rigid", (0, 0, 0), {}), ("/World/PrimB", "rigid", (1, 0, 0), {})],
                 ["/World/PrimA", "/World/PrimB"])
    assert {len(both[name]) for name in ("parentFrames", "childFrames", "translations", "orientations")} == {2}


def test_no_target_prims_is_refused(tmp_path):
    """Isaac logs "Please specify at least one valid target prim" and writes nothing; graphflow stops the run
    with that as a one-line error (nothing is silently skipped)."""
    with pytest.raises(GraphRuntimeError, match="targetPrims is not set"):
        _tree(tmp_path, [("/World/Cube", "rigid", (0, 0, 1), {})], [])


def test_orientation_of_a_turned_cube_is_a_unit_quaternion(tmp_path):
    """Isaac: a cube turned 45 degrees about z (w 0.9238795, z 0.3826834) reads a unit quaternion; it is that
    rotation."""
    outputs = _tree(tmp_path, [("/World/Cube", "rigid", (0, 0, 0), {"orient": (0.9238795, 0, 0, 0.3826834)})],
                    ["/World/Cube"])
    x, y, z, w = outputs["orientations"][0]
    assert x * x + y * y + z * z + w * w == pytest.approx(1.0, abs=0.01)
    assert (x, y, z, w) == pytest.approx((0.0, 0.0, 0.3826834, 0.9238795), abs=1e-4)


def test_sensors_on_rigid_bodies_follow_them(tmp_path):
    """Isaac: an IMU Xform 1 m along y of a rigid body at x 3 reads (3, 1, 0) (within 0.5); a sensor 0.5 along y
    of a mount 1 m along x of a body at the origin reads (1, 0.5, 0); both move with the falling body."""
    outputs = _by_child(_tree(tmp_path, [("/World/RigidBody", "rigid", (3, 0, 0), {}),
                                         ("/World/RigidBody/IMU", "xform", (0, 1, 0), {})],
                              ["/World/RigidBody", "/World/RigidBody/IMU"]))
    assert set(outputs) == {"RigidBody", "IMU"}
    assert outputs["IMU"][1] == pytest.approx((3.0, 1.0, -FALL), abs=0.01)
    chain = _by_child(_tree(tmp_path, [("/World/Body", "rigid", (0, 0, 0), {}),
                                       ("/World/Body/Mount", "xform", (1, 0, 0), {}),
                                       ("/World/Body/Mount/Sensor", "xform", (0, 0.5, 0), {})],
                            ["/World/Body", "/World/Body/Mount/Sensor"]))
    assert chain["Sensor"][1] == pytest.approx((1.0, 0.5, -FALL), abs=0.01)


def test_relative_to_non_physics_parents(tmp_path):
    """Isaac: a body at world (5, 3, 0) under an Xform at x 5 reads (0, 3, 0) relative to it; a lidar 0.5 above a
    body at x 10 reads (0, 0, 0.5) relative to the body; relative to a mount 1 m along y of a chassis, a lidar
    0.5 above the mount reads (0, 0, 0.5)."""
    frame = _tree(tmp_path, [("/World/Frame", "xform", (5, 0, 0), {}), ("/World/Frame/Body", "rigid", (0, 3, 0), {})],
                  ["/World/Frame/Body"], parent="/World/Frame")
    assert frame["translations"][0] == pytest.approx((0.0, 3.0, -FALL), abs=0.01)
    lidar = _tree(tmp_path, [("/World/Bot", "rigid", (10, 0, 0), {}), ("/World/Bot/Lidar", "xform", (0, 0, 0.5), {})],
                  ["/World/Bot/Lidar"], parent="/World/Bot")
    assert lidar["translations"][0] == pytest.approx((0.0, 0.0, 0.5), abs=1e-6)
    mount = _tree(tmp_path, [("/World/Chassis", "rigid", (2, 0, 0), {}),
                             ("/World/Chassis/SensorMount", "xform", (0, 1, 0), {}),
                             ("/World/Chassis/SensorMount/Lidar", "xform", (0, 0, 0.5), {})],
                  ["/World/Chassis/SensorMount/Lidar"], parent="/World/Chassis/SensorMount")
    assert mount["translations"][0] == pytest.approx((0.0, 0.0, 0.5), abs=1e-6)
    assert mount["parentFrames"] == ("SensorMount",)


def test_camera_frames_are_turned_to_the_ros_optical_convention(tmp_path):
    """Isaac: a camera under a rigid body is turned 180 degrees about its x axis (USD cameras look down -z, ROS
    optical frames down +z): orientation x ~ +-1, w ~ 0."""
    outputs = _by_child(_tree(tmp_path, [("/World/CamBody", "rigid", (0, 0, 0), {}),
                                         ("/World/CamBody/Camera", "camera", (0, 0, 0.5), {})],
                              ["/World/CamBody", "/World/CamBody/Camera"]))
    x, y, z, w = outputs["Camera"][2]
    assert abs(x) == pytest.approx(1.0, abs=1e-6) and (y, z, w) == pytest.approx((0.0, 0.0, 0.0), abs=1e-6)
    assert outputs["CamBody"][2] == pytest.approx((0.0, 0.0, 0.0, 1.0), abs=1e-6)


def test_mixed_and_non_physics_targets(tmp_path):
    """Isaac: a rigid cube at x 1 and an Xform at y 2 both hang off world; two Xforms at (1, 2, 0) and (0, 0, 3)
    read their translations."""
    mixed = _by_child(_tree(tmp_path, [("/World/Rigid", "rigid", (1, 0, 0), {}), ("/World/Xform", "xform", (0, 2, 0), {})],
                            ["/World/Rigid", "/World/Xform"]))
    assert mixed["Rigid"][1][0] == pytest.approx(1.0, abs=1e-6) and mixed["Xform"][1] == pytest.approx((0, 2, 0))
    assert {parent for parent, _, _ in mixed.values()} == {"world"}
    plain = _by_child(_tree(tmp_path, [("/World/XformA", "xform", (1, 2, 0), {}), ("/World/XformB", "xform", (0, 0, 3), {})],
                            ["/World/XformA", "/World/XformB"]))
    assert plain["XformA"][1] == pytest.approx((1, 2, 0)) and plain["XformB"][1] == pytest.approx((0, 0, 3))


def test_name_overrides_name_the_frames(tmp_path):
    """Isaac: isaac:nameOverride 'base_frame' on the parent and 'sensor_frame' on the child are the frame names;
    without overrides the parent frame is the parent prim's name."""
    named = _tree(tmp_path, [("/World/ParentXform", "xform", (0, 0, 0), {"name": "base_frame"}),
                             ("/World/ParentXform/ChildXform", "xform", (1, 0, 0), {"name": "sensor_frame"})],
                  ["/World/ParentXform/ChildXform"], parent="/World/ParentXform")
    assert (named["parentFrames"], named["childFrames"]) == (("base_frame",), ("sensor_frame",))
    plain = _tree(tmp_path, [("/World/Frame", "xform", (0, 0, 0), {}), ("/World/Frame/Leaf", "xform", (0, 1, 0), {})],
                  ["/World/Frame/Leaf"], parent="/World/Frame")
    assert (plain["parentFrames"], plain["childFrames"]) == (("Frame",), ("Leaf",))


def test_ancestor_scale_rotation_and_reset_xform_stack(tmp_path):
    """Isaac: a sensor 1 m along x of a mount scaled 2 reads x 2 (within 0.1); of a mount turned 90 degrees about
    z reads (0, 1); with !resetXformStack! under a mount at x 10 scaled 2 it reads (1, 0, 0); under a mount scaled
    3 its orientation stays a unit quaternion. References: the composed USD transforms."""
    scaled = _tree(tmp_path, [("/World/ScaledMount", "xform", (0, 0, 0), {"scale": (2, 2, 2)}),
                              ("/World/ScaledMount/Sensor", "xform", (1, 0, 0), {})], ["/World/ScaledMount/Sensor"])
    assert scaled["translations"][0] == pytest.approx((2.0, 0.0, 0.0), abs=1e-6)
    turned = _tree(tmp_path, [("/World/RotatedMount", "xform", (0, 0, 0), {"orient": (0.7071068, 0, 0, 0.7071068)}),
                              ("/World/RotatedMount/Sensor", "xform", (1, 0, 0), {})], ["/World/RotatedMount/Sensor"])
    assert turned["translations"][0] == pytest.approx((0.0, 1.0, 0.0), abs=1e-6)
    reset = _tree(tmp_path, [("/World/Mount", "xform", (10, 0, 0), {"scale": (2, 2, 2)}),
                             ("/World/Mount/Sensor", "xform", (1, 0, 0), {"reset": True})], ["/World/Mount/Sensor"])
    assert reset["translations"][0] == pytest.approx((1.0, 0.0, 0.0), abs=1e-6)
    big = _tree(tmp_path, [("/World/ScaledMount", "xform", (0, 0, 0), {"scale": (3, 3, 3)}),
                           ("/World/ScaledMount/Sensor", "xform", (1, 0, 0), {})], ["/World/ScaledMount/Sensor"])
    assert math.fsum(c * c for c in big["orientations"][0]) == pytest.approx(1.0, abs=1e-9)


def test_parent_rotation_turns_the_relative_translation(tmp_path):
    """Isaac: a body at world (1, 0, 0) relative to a parent Xform turned 90 degrees about z reads (0, -1) (within
    0.2): the world offset turned by the parent's inverse rotation."""
    outputs = _tree(tmp_path, [("/World/RotatedParent", "xform", (0, 0, 0), {"orient": (0.7071068, 0, 0, 0.7071068)}),
                               ("/World/Child", "rigid", (1, 0, 0), {})], ["/World/Child"], parent="/World/RotatedParent")
    assert outputs["translations"][0] == pytest.approx((0.0, -1.0, -FALL), abs=0.01)


def test_intermediate_reset_shared_mounts_and_self_parent(tmp_path):
    """Isaac: !resetXformStack! on a middle prim drops the outer (+10) but keeps the chain below: 5 + 1 = 6; two
    sensors on one mount (1, 2, 0) keep their own offsets (z +1 and -1); with the body itself as parentPrim
    the body reads 0 and its sensor its local 0.3."""
    middle = _tree(tmp_path, [("/World/Outer", "xform", (10, 0, 0), {}),
                              ("/World/Outer/ResetMid", "xform", (5, 0, 0), {"reset": True}),
                              ("/World/Outer/ResetMid/Sensor", "xform", (1, 0, 0), {})], ["/World/Outer/ResetMid/Sensor"])
    assert middle["translations"][0] == pytest.approx((6.0, 0.0, 0.0), abs=1e-6)
    shared = _by_child(_tree(tmp_path, [("/World/Body", "rigid", (0, 0, 0), {}),
                                        ("/World/Body/Mount", "xform", (1, 2, 0), {}),
                                        ("/World/Body/Mount/SensorA", "xform", (0, 0, 1), {}),
                                        ("/World/Body/Mount/SensorB", "xform", (0, 0, -1), {})],
                             ["/World/Body/Mount/SensorA", "/World/Body/Mount/SensorB"]))
    assert shared["SensorA"][1] == pytest.approx((1.0, 2.0, 1.0 - FALL), abs=0.01)
    assert shared["SensorB"][1] == pytest.approx((1.0, 2.0, -1.0 - FALL), abs=0.01)
    itself = _by_child(_tree(tmp_path, [("/World/Body", "rigid", (7, 0, 0), {}),
                                        ("/World/Body/Sensor", "xform", (0, 0, 0.3), {})],
                             ["/World/Body", "/World/Body/Sensor"], parent="/World/Body"))
    assert itself["Body"][1] == pytest.approx((0.0, 0.0, 0.0), abs=1e-9)
    assert itself["Sensor"][1] == pytest.approx((0.0, 0.0, 0.3), abs=1e-9)


@pytest.mark.parametrize(("kind", "schemas", "turned"), [
    ("omnilidar", ("OmniSensorGenericLidarCoreAPI",), False), ("camera", ("OmniSensorAPI",), True),
    ("camera", ("IsaacRtxLidarSensorAPI",), False)])
def test_lidars_are_not_turned_rtx_cameras_are(tmp_path, kind, schemas, turned):
    """Isaac: an OmniLidar (new RTX lidar schema) and a Camera carrying IsaacRtxLidarSensorAPI (legacy RTX lidar)
    keep the identity; a Camera with OmniSensorAPI (an RTX camera) is turned 180 degrees about x."""
    outputs = _by_child(_tree(tmp_path, [("/World/Body", "rigid", (0, 0, 0), {}),
                                         ("/World/Body/Sensor", kind, (0, 0, 0.5), {"schemas": schemas})],
                              ["/World/Body", "/World/Body/Sensor"]))
    expected = (1.0, 0.0, 0.0, 0.0) if turned else (0.0, 0.0, 0.0, 1.0)
    assert outputs["Sensor"][2] == pytest.approx(expected, abs=1e-6)
    assert outputs["Sensor"][1][2] == pytest.approx(0.5 - FALL, abs=0.01)


def test_a_named_camera_under_a_scaled_mount(tmp_path):
    """Isaac: a camera 1 m up under a mount scaled 2 reads z 2, turned, with a unit quaternion; a camera named
    'front_rgb' by isaac:nameOverride is published under that name, still turned."""
    scaled = _tree(tmp_path, [("/World/Mount", "xform", (0, 0, 0), {"scale": (2, 2, 2)}),
                              ("/World/Mount/Camera", "camera", (0, 0, 1), {})], ["/World/Mount/Camera"])
    assert scaled["translations"][0] == pytest.approx((0.0, 0.0, 2.0), abs=1e-6)
    assert scaled["orientations"][0] == pytest.approx((1.0, 0.0, 0.0, 0.0), abs=1e-6)
    named = _by_child(_tree(tmp_path, [("/World/Body", "rigid", (0, 0, 0), {}),
                                       ("/World/Body/Camera", "camera", (0, 0, 0.5), {"name": "front_rgb"})],
                            ["/World/Body", "/World/Body/Camera"]))
    assert named["front_rgb"][2] == pytest.approx((1.0, 0.0, 0.0, 0.0), abs=1e-6)


def test_a_sensor_follows_its_body_when_the_body_is_moved(tmp_path):
    """Isaac: a body moved to x 4 carries its sensor (1 m above) there: x within 0.5 of 4, z of 1."""
    with create_world(_stage(tmp_path, [("/World/Body", "rigid", (0, 0, 0), {}),
                                        ("/World/Body/Sensor", "xform", (0, 0, 1), {})]), time_step=1 / 60) as world:
        node = NodeHarness(TREE, {"targetPrims": ["/World/Body/Sensor"]}, world=world)
        for _ in range(WARM_UP):
            world.step()
        before = node.compute("execIn").outputs["translations"][0]
        world.set_attribute("/World/Body", "xformOp:translate", (4.0, 0.0, 0.0))
        for _ in range(5):
            world.step()
        after = node.compute("execIn").outputs["translations"][0]
    assert before == pytest.approx((0.0, 0.0, 1.0 - FALL), abs=0.01)
    assert after[0] == pytest.approx(4.0, abs=1e-6) and after[2] == pytest.approx(1.0, abs=0.05)



def test_shared_override_goes_to_the_deepest_prim_and_duplicate_names_are_qualified(tmp_path):
    """Isaac: a mount and its sensor both named 'shared_frame' by override: only the deeper sensor keeps it (the
    mount falls back to 'Mount'); two links both called 'Link' under RobotA and RobotB: one keeps 'Link', the
    other becomes 'RobotB_Link'."""
    shared = _tree(tmp_path, [("/World/Mount", "xform", (0, 0, 0), {"name": "shared_frame"}),
                              ("/World/Mount/Sensor", "xform", (0, 0, 1), {"name": "shared_frame"})],
                   ["/World/Mount", "/World/Mount/Sensor"])
    assert shared["childFrames"] == ("Mount", "shared_frame")
    links = _tree(tmp_path, [("/World/RobotA", "rigid", (0, 0, 0), {}), ("/World/RobotA/Link", "xform", (0, 0, 0.1), {}),
                             ("/World/RobotB", "rigid", (5, 0, 0), {}), ("/World/RobotB/Link", "xform", (0, 0, 0.1), {})],
                  ["/World/RobotA/Link", "/World/RobotB/Link"])
    assert links["childFrames"] == ("Link", "RobotB_Link")
