"""ROS2PublishTransformTree and ROS2PublishRawTransformTree: tf2_msgs/TFMessage on the topic bus."""
import math

import pytest

pytest.importorskip("rosbags")

from graphflow.poses import quat_from_axis_angle  # noqa: E402
from graphflow.ros2.bus import topic_bus_for  # noqa: E402
from graphflow.testing import NodeHarness  # noqa: E402
from graphflow.testing.fake_world import FakeWorld  # noqa: E402

BRIDGE = "isaacsim.ros2.bridge."
YAW_90 = quat_from_axis_angle((0.0, 0.0, 1.0), math.pi / 2)


def _transforms(world):
    (message,) = topic_bus_for(world).published
    assert (message.topic, message.type) == ("/tf", "tf2_msgs/msg/TFMessage")
    return {(t["header"]["frame_id"], t["child_frame_id"]): t["transform"] for t in message.message["transforms"]}


def test_raw_transform_tree_publishes_the_given_transform():
    node = NodeHarness(BRIDGE + "ROS2PublishRawTransformTree",
                       {"translation": [1.0, 2.0, 3.0], "rotation": list(YAW_90), "timeStamp": 2.5})
    node.compute("execIn")
    (message,) = topic_bus_for(node.world).published
    (transform,) = message.message["transforms"]
    assert transform["header"] == {"stamp": {"sec": 2, "nanosec": 500_000_000}, "frame_id": "odom"}
    assert transform["child_frame_id"] == "base_link"
    assert transform["transform"]["translation"] == {"x": 1.0, "y": 2.0, "z": 3.0}


def _two_link_robot():
    from pxr import Sdf, Usd, UsdGeom, UsdPhysics

    stage = Usd.Stage.CreateInMemory()
    UsdGeom.Xform.Define(stage, "/Robot")
    for link in ("base", "arm"):
        UsdPhysics.RigidBodyAPI.Apply(UsdGeom.Xform.Define(stage, f"/Robot/{link}").GetPrim())
    joint = UsdPhysics.RevoluteJoint.Define(stage, "/Robot/base/joint")
    joint.CreateBody0Rel().SetTargets([Sdf.Path("/Robot/base")])
    joint.CreateBody1Rel().SetTargets([Sdf.Path("/Robot/arm")])
    world = FakeWorld(0.1, stage=stage)
    world.add_box("/Robot/base", (1.0, 0.0, 0.0), (0.1, 0.1, 0.1), orientation=YAW_90)
    world.add_box("/Robot/arm", (1.0, 1.0, 0.5), (0.1, 0.1, 0.1), orientation=YAW_90)
    world.add_box("/World/cube", (0.0, 3.0, 0.0), (0.1, 0.1, 0.1))
    return world


def test_an_articulation_publishes_each_link_from_the_link_it_hangs_on():
    world = _two_link_robot()
    node = NodeHarness(BRIDGE + "ROS2PublishTransformTree", {"targetPrims": ["/Robot", "/World/cube"]}, world=world)
    node.compute("execIn")
    transforms = _transforms(world)
    assert set(transforms) == {("world", "base"), ("base", "arm"), ("world", "cube")}
    # the arm is 1 m along world +y and 0.5 m up from the base; the base faces +y, so that is its +x
    arm = transforms[("base", "arm")]
    assert [arm["translation"][a] for a in "xyz"] == pytest.approx([1.0, 0.0, 0.5], abs=1e-12)
    assert [arm["rotation"][a] for a in "xyzw"] == pytest.approx([0.0, 0.0, 0.0, 1.0], abs=1e-12)
    assert transforms[("world", "cube")]["translation"] == {"x": 0.0, "y": 3.0, "z": 0.0}


def test_a_parent_prim_frames_the_poses_and_given_arrays_pass_through():
    world = _two_link_robot()
    node = NodeHarness(BRIDGE + "ROS2PublishTransformTree",
                       {"parentPrim": ["/Robot/base"], "targetPrims": ["/World/cube"]}, world=world)
    node.compute("execIn")
    cube = _transforms(world)[("base", "cube")]
    # the cube (-1, 3, 0) from the base, in a frame turned 90 deg: x' = y, y' = -x
    assert [cube["translation"][a] for a in "xyz"] == pytest.approx([3.0, 1.0, 0.0], abs=1e-12)
    given = NodeHarness(BRIDGE + "ROS2PublishTransformTree",
                        {"parentFrames": ["map"], "childFrames": ["odom"], "translations": [[1.0, 0.0, 0.0]],
                         "orientations": [[0.0, 0.0, 0.0, 1.0]]})
    given.compute("execIn")
    assert _transforms(given.world)[("map", "odom")]["translation"]["x"] == 1.0


def test_compute_transform_tree_gives_stage_units_and_publish_turns_them_into_metres():
    from pxr import UsdGeom

    world = _two_link_robot()
    UsdGeom.SetStageMetersPerUnit(world.stage, 0.01)
    tree = NodeHarness("isaacsim.core.nodes.IsaacComputeTransformTree", {"targetPrims": ["/Robot"]}, world=world)
    outputs = tree.compute("execIn").outputs
    assert outputs["parentFrames"] == ("world", "base") and outputs["childFrames"] == ("base", "arm")
    assert outputs["translations"][1] == pytest.approx((100.0, 0.0, 50.0), abs=1e-9)   # 1 m, 0.5 m in centimetres
    publish = NodeHarness(BRIDGE + "ROS2PublishTransformTree", {
        "parentFrames": list(outputs["parentFrames"]), "childFrames": list(outputs["childFrames"]),
        "translations": [list(t) for t in outputs["translations"]],
        "orientations": [list(q) for q in outputs["orientations"]]}, world=world)
    publish.compute("execIn")
    arm = _transforms(world)[("base", "arm")]
    assert [arm["translation"][a] for a in "xyz"] == pytest.approx([1.0, 0.0, 0.5], abs=1e-9)


def test_clock_subscriber_and_qos_profile():
    import json

    from graphflow.ros2.timeline import ScriptedMessage, ScriptedTopics

    node = NodeHarness(BRIDGE + "ROS2SubscribeClock")
    topic_bus_for(node.world).add_transport(ScriptedTopics([
        ScriptedMessage("/clock", 0.0, {"clock": {"sec": 12, "nanosec": 500_000_000}})]))
    node.tick()
    result = node.compute("execIn")
    assert result.fired == {"execOut"} and result.outputs["timeStamp"] == 12.5
    assert node.compute("execIn").fired == set()     # each message once
    qos = NodeHarness(BRIDGE + "ROS2QoSProfile", {"depth": 5, "reliability": "bestEffort"}).compute()
    assert json.loads(qos.outputs["qosProfile"]) == {
        "history": "keepLast", "depth": 5, "reliability": "bestEffort", "durability": "volatile", "deadline": 0.0,
        "lifespan": 0.0, "liveliness": "systemDefault", "leaseDuration": 0.0}


def test_a_name_override_names_the_published_frame():
    """Isaac's pose tree names a frame by the prim's isaac:nameOverride when one is authored."""
    from pxr import Sdf, Usd

    stage = Usd.Stage.CreateInMemory()
    stage.DefinePrim("/World/cube", "Xform").CreateAttribute("isaac:nameOverride", Sdf.ValueTypeNames.String).Set(
        "cube_link")
    world = FakeWorld(0.1, stage=stage)
    world.add_box("/World/cube", (0.0, 3.0, 0.0), (0.1, 0.1, 0.1))
    node = NodeHarness(BRIDGE + "ROS2PublishTransformTree", {"targetPrims": ["/World/cube"]}, world=world)
    node.compute("execIn")
    assert set(_transforms(world)) == {("world", "cube_link")}


def test_duplicate_frame_names_take_their_path_as_isaacs_pose_tree():
    """Isaac's test_duplicate_names_tree: three cubes all called 'cube' (the third renamed 'Cube_override'),
    relative to the first: the first is 'cube', the second 'cube1_cube', the third its override."""
    from pxr import Sdf, Usd

    stage = Usd.Stage.CreateInMemory()
    world = FakeWorld(0.1, stage=stage)
    for index in range(3):
        stage.DefinePrim(f"/cube{index}/cube", "Cube")
        world.add_box(f"/cube{index}/cube", (2.0 + index, 0.0, 0.75), (0.75, 0.75, 0.75))
    stage.GetPrimAtPath("/cube2/cube").CreateAttribute("isaac:nameOverride", Sdf.ValueTypeNames.String).Set(
        "Cube_override")
    node = NodeHarness(BRIDGE + "ROS2PublishTransformTree",
                       {"targetPrims": ["/cube1/cube", "/cube2/cube"], "parentPrim": ["/cube0/cube"]}, world=world)
    node.compute("execIn")
    transforms = _transforms(world)
    assert set(transforms) == {("cube", "cube1_cube"), ("cube", "Cube_override")}
    assert [transforms[("cube", "cube1_cube")]["translation"][a] for a in "xyz"] == pytest.approx([1.0, 0.0, 0.0])
