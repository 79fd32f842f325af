"""ROS2SubscribeTransformTree: /tf places free bodies (PyBullet world of the packaged UR10 cell)."""
import math

import pytest

from graphflow.executor import GraphRuntimeError
from graphflow.physics import create_world
from graphflow.poses import quat_from_axis_angle, quat_rotate
from graphflow.ros2.bus import topic_bus_for
from graphflow.testing import GraphHarness

STAGE = "asset:ur10_pick_place.usda"
SUBSCRIBE = "isaacsim.ros2.bridge.ROS2SubscribeTransformTree"
YAW_90 = quat_from_axis_angle((0.0, 0.0, 1.0), math.pi / 2)


def _stamped(parent, child, translation, rotation=(0.0, 0.0, 0.0, 1.0)):
    return {"header": {"stamp": {"sec": 0, "nanosec": 0}, "frame_id": parent}, "child_frame_id": child,
            "transform": {"translation": dict(zip("xyz", translation)), "rotation": dict(zip("xyzw", rotation))}}


def _graph(world, **inputs):
    return GraphHarness({
        "nodes": [{"name": "tick", "type": "omni.graph.action.OnPlaybackTick"},
                  {"name": "tf", "type": SUBSCRIBE, "inputs": inputs}],
        "connections": [{"src": "tick.outputs:tick", "dst": "tf.inputs:execIn"}],
    }, world=world)


def test_a_free_body_is_placed_at_the_parent_frame_composed_with_the_transform_and_stays():
    with create_world(STAGE) as world:
        graph = _graph(world, frameNamesMap=["/World/ur10", "robot", "/World/Cube", "cube"])
        robot_position, robot_rotation = world.prim_pose("/World/ur10")
        offset, turn = (0.5, -0.2, 0.4), YAW_90
        topic_bus_for(world).publish("/tf", "tf2_msgs/msg/TFMessage",
                                     {"transforms": [_stamped("robot", "cube", offset, turn),
                                                     _stamped("robot", "unmapped", (9.0, 9.0, 9.0))]})
        graph.run(1)
        # by hand: the cube's world position is the robot's position plus the offset turned by the robot
        expected = tuple(p + o for p, o in zip(robot_position, quat_rotate(robot_rotation, offset)))
        position, rotation = world.prim_pose("/World/Cube")
        assert position == pytest.approx(expected, abs=1e-6)
        assert abs(sum(a * b for a, b in zip(rotation, YAW_90))) == pytest.approx(1.0, abs=1e-6)
        graph.run(30)                                     # half a second later it has not fallen
        assert world.prim_pose("/World/Cube")[0] == pytest.approx(expected, abs=1e-6)
        assert world.gravity_enabled("/World/Cube") is False


def test_articulations_and_bad_maps_fail_with_one_line_naming_them():
    with create_world(STAGE) as world:
        link = "/World/ur10/wrist_1_link"
        graph = _graph(world, frameNamesMap=["/World", "world", link, "wrist"])
        topic_bus_for(world).publish("/tf", "tf2_msgs/msg/TFMessage",
                                     {"transforms": [_stamped("world", "wrist", (0.5, 0.0, 0.5))]})
        with pytest.raises(GraphRuntimeError, match=f"{link}: .*free body"):
            graph.run(1)
        with pytest.raises(GraphRuntimeError, match="articulationRoots: /World/ur10: graphflow's world cannot"):
            _graph(world, articulationRoots=["/World/ur10"]).run(1)
        with pytest.raises(GraphRuntimeError, match="no prim /World/Nothing"):
            _graph(world, frameNamesMap=["/World/Nothing", "x"]).run(1)
        with pytest.raises(GraphRuntimeError, match="even length"):
            _graph(world, frameNamesMap=["/World/Cube"]).run(1)
