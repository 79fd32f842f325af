"""The topic bus, scripted topics and the ROS 2 bridge nodes, on a plain clock world."""
import json
import math

import pytest

pytest.importorskip("rosbags")

from graphflow.cli import main  # noqa: E402
from graphflow.document import GraphError  # noqa: E402
from graphflow.executor import GraphRuntimeError  # noqa: E402
from graphflow.ros2.bus import topic_bus_for  # noqa: E402
from graphflow.ros2.messages import MessageError, complete, stamp  # noqa: E402
from graphflow.ros2.timeline import (  # noqa: E402
    ScriptedMessage,
    ScriptedTopics,
    TopicSpecError,
    parse_topic_spec,
)
from graphflow.testing import ClockWorld, GraphHarness, NodeHarness  # noqa: E402

BRIDGE = "isaacsim.ros2.bridge."


def _published(world):
    return [(m.topic, m.type, m.message) for m in topic_bus_for(world).published]


def test_clock_publishes_the_time_stamp_as_sec_and_nanosec():
    node = NodeHarness(BRIDGE + "ROS2PublishClock", {"timeStamp": 1.25})
    node.compute("execIn")
    assert _published(node.world) == [("/clock", "rosgraph_msgs/msg/Clock", {"clock": {"sec": 1, "nanosec": 250_000_000}})]


def test_topic_names_resolve_against_the_namespace_as_ros_does():
    node = NodeHarness(BRIDGE + "ROS2PublishClock", {"nodeNamespace": "robot1", "topicName": "clock"})
    node.compute("execIn")
    absolute = NodeHarness(BRIDGE + "ROS2PublishClock", {"nodeNamespace": "robot1", "topicName": "/clock"},
                           world=node.world)
    absolute.compute("execIn")
    assert [topic for topic, _, _ in _published(node.world)] == ["/robot1/clock", "/clock"]


def test_twist_subscriber_takes_each_message_once_when_it_is_due():
    world = ClockWorld(0.1)
    topic_bus_for(world).add_transport(ScriptedTopics([
        ScriptedMessage("/cmd_vel", 0.2, {"linear": {"x": 0.5}, "angular": {"z": -0.25}})]))
    node = NodeHarness(BRIDGE + "ROS2SubscribeTwist", world=world)
    fired = [bool(node.tick("execIn").fired) for _ in range(4)]
    assert fired == [False, True, False, False]   # delivered after the step that reaches t = 0.2 s, taken once
    assert node.outputs.linearVelocity == (0.5, 0.0, 0.0)
    assert node.outputs.angularVelocity == (0.0, 0.0, -0.25)


def test_world_reset_replays_the_timeline():
    harness = GraphHarness({
        "settings": {"timeStep": 0.1},
        "nodes": [{"name": "tick", "type": "omni.graph.action.OnTick"},
                  {"name": "sub", "type": BRIDGE + "ROS2SubscribeJointState"}],
        "connections": [{"src": "tick.outputs:tick", "dst": "sub.inputs:execIn"}]})
    topic_bus_for(harness.world).add_transport(ScriptedTopics([
        ScriptedMessage("/joint_command", 0.1, {"name": ["a", "b"], "position": [0.1, 0.2]})]))
    harness.run(3)
    assert harness.output("sub", "positionCommand") == (0.1, 0.2)
    harness.reset()
    assert harness.output("sub", "positionCommand") == ()
    harness.run(1)
    assert harness.output("sub", "jointNames") == ("a", "b")


def test_a_message_that_does_not_fit_the_subscribers_type_is_a_run_time_error_naming_the_field():
    world = ClockWorld(0.1)
    topic_bus_for(world).add_transport(ScriptedTopics([ScriptedMessage("/cmd_vel", 0.0, {"linear": {"w": 1}})]))
    node = NodeHarness(BRIDGE + "ROS2SubscribeTwist", world=world)
    with pytest.raises(GraphRuntimeError, match=r"topic /cmd_vel\.linear: geometry_msgs/msg/Vector3 has no field w"):
        node.tick("execIn")


def test_odometry_velocities_projected_on_the_robot_front_unless_raw():
    """As Isaac's node: the velocities (IsaacComputeOdometry's, already in the chassis frame) are projected on the
    fixed axes robotFront, up x front and up, whatever the orientation; raw ones go out as given. Isaac's
    test_ros2_odometry sets robotFront (0, 1, 0): a velocity along +y is then forward, one along +x to the right."""
    yaw_90 = (0.0, 0.0, math.sin(math.pi / 4), math.cos(math.pi / 4))
    inputs = {"orientation": yaw_90, "linearVelocity": (0.0, 2.0, 0.0), "position": (1.0, 2.0, 0.0), "timeStamp": 0.5,
              "angularVelocity": (0.0, 0.0, 0.5)}
    node = NodeHarness(BRIDGE + "ROS2PublishOdometry", inputs)
    node.compute("execIn")
    node.set_inputs(publishRawVelocities=True)
    node.compute("execIn")
    node.set_inputs(publishRawVelocities=False, robotFront=(0.0, 3.0, 7.0), linearVelocity=(1.0, 2.0, 0.0))
    node.compute("execIn")
    chassis, raw, turned = (message for _, _, message in _published(node.world))
    assert [chassis["twist"]["twist"]["linear"][a] for a in "xyz"] == [0.0, 2.0, 0.0]
    assert [raw["twist"]["twist"]["linear"][a] for a in "xyz"] == [0.0, 2.0, 0.0]
    # front (0, 1, 0) (z dropped, normalised), side = up x front = (-1, 0, 0), up (0, 0, 1)
    assert [turned["twist"]["twist"]["linear"][a] for a in "xyz"] == [2.0, -1.0, 0.0]
    assert [turned["twist"]["twist"]["angular"][a] for a in "xyz"] == [0.0, 0.0, 0.5]
    assert chassis["header"] == {"stamp": {"sec": 0, "nanosec": 500_000_000}, "frame_id": "odom"}
    assert chassis["child_frame_id"] == "base_link" and chassis["pose"]["pose"]["position"]["x"] == 1.0


def test_imu_parts_left_out_carry_the_no_estimate_covariance():
    node = NodeHarness(BRIDGE + "ROS2PublishImu", {"publishOrientation": False, "linearAcceleration": (0.0, 0.0, 9.81)})
    node.compute("execIn")
    (_, type_name, message), = _published(node.world)
    assert type_name == "sensor_msgs/msg/Imu"
    assert message["orientation_covariance"][0] == -1.0 and message["angular_velocity_covariance"][0] == 0.0
    assert message["linear_acceleration"]["z"] == 9.81


def test_generic_publisher_fills_isaacs_field_paths_and_defaults():
    fields = {"header:frame_id": "world", "pose:pose:position:z": -3.5, "pose:covariance": [0.5] + [0.0] * 35}
    node = NodeHarness(BRIDGE + "ROS2Publisher", {"topicName": "/depth", "messagePackage": "geometry_msgs",
                                                  "messageName": "PoseWithCovarianceStamped",
                                                  "messageFields": json.dumps(fields)})
    node.compute("execIn")
    (topic, type_name, message), = _published(node.world)
    assert (topic, type_name) == ("/depth", "geometry_msgs/msg/PoseWithCovarianceStamped")
    assert message["pose"]["pose"]["position"] == {"x": 0.0, "y": 0.0, "z": -3.5}
    assert message["header"]["frame_id"] == "world" and message["pose"]["covariance"][0] == 0.5


def test_generic_publisher_rejects_bad_fields_at_load_and_unknown_types_at_run():
    with pytest.raises(GraphError, match="inputs:messageFields: not JSON"):
        NodeHarness(BRIDGE + "ROS2Publisher", {"messageFields": "{x"})
    node = NodeHarness(BRIDGE + "ROS2Publisher", {"messagePackage": "my_msgs", "messageName": "Thing"})
    with pytest.raises(GraphRuntimeError, match="unknown ROS 2 message type 'my_msgs/msg/Thing'"):
        node.compute("execIn")


def test_generic_subscriber_outputs_the_whole_message_as_json():
    world = ClockWorld(0.1)
    topic_bus_for(world).add_transport(ScriptedTopics([ScriptedMessage("/thrusters", 0.0, {"data": [1, 2.5]})]))
    node = NodeHarness(BRIDGE + "ROS2Subscriber", {"topicName": "/thrusters", "messageName": "Float32MultiArray"},
                       world=world)
    assert node.tick("execIn").fired == {"execOut"}
    assert json.loads(node.outputs.message)["data"] == [1.0, 2.5]


def test_context_handle_names_the_domain(monkeypatch):
    monkeypatch.delenv("ROS_DOMAIN_ID", raising=False)
    assert NodeHarness(BRIDGE + "ROS2Context", {"domain_id": 7}).compute().outputs["context"] == 8
    monkeypatch.setenv("ROS_DOMAIN_ID", "3")
    assert NodeHarness(BRIDGE + "ROS2Context", {"domain_id": 7}).compute().outputs["context"] == 4


def test_messages_are_checked_against_the_standard_definitions():
    assert complete("sensor_msgs/JointState", {"name": ["j"], "position": [1]})["position"] == [1.0]
    assert stamp(2.000000001) == {"sec": 2, "nanosec": 1}
    with pytest.raises(MessageError, match=r"message\.position\[0\]: expected a number, got 'x'"):
        complete("sensor_msgs/msg/JointState", {"position": ["x"]})


@pytest.mark.parametrize("spec, problem", [
    ("/cmd_vel@1.0={bad", "the message is not JSON"),
    ("/cmd_vel=1", "expected TOPIC@TIME=JSON"),
    ("bad topic@1={}", "topic must be a ROS 2 name"),
])
def test_bad_topic_specs_name_the_entry(spec, problem):
    with pytest.raises(TopicSpecError, match=problem):
        parse_topic_spec(spec)


def test_bad_topics_file_is_one_line_and_exit_2(tmp_path, capsys):
    topics = tmp_path / "topics.json"
    topics.write_text(json.dumps({"topics": [{"topic": "/joint_command", "time": 0.5,
                                              "type": "sensor_msgs/msg/JointState", "message": {"names": ["a"]}}]}))
    graph = tmp_path / "g.json"
    assert main(["new", str(graph)]) == 0
    assert main(["run", str(graph), "--topics", str(topics)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "topics[0]: message: sensor_msgs/msg/JointState has no field names" in err[0]


def test_an_ackermann_drive_published_is_the_drive_its_subscriber_reads():
    publisher = NodeHarness(BRIDGE + "ROS2PublishAckermannDrive",
                            {"timeStamp": 2.5, "frameId": "base_link", "steeringAngle": 0.3, "speed": 1.5,
                             "acceleration": 0.5})
    publisher.compute("execIn")
    (topic, type_name, message), = _published(publisher.world)
    assert (topic, type_name) == ("/ackermann_cmd", "ackermann_msgs/msg/AckermannDriveStamped")
    assert message["header"] == {"stamp": {"sec": 2, "nanosec": 500_000_000}, "frame_id": "base_link"}
    reader = NodeHarness(BRIDGE + "ROS2SubscribeAckermannDrive", world=publisher.world)
    assert reader.compute("execIn").fired == {"execOut"}
    out = reader.outputs
    assert (out.frameId, out.timeStamp, out.speed, out.acceleration, out.jerk) == ("base_link", 2.5, 1.5, 0.5, 0.0)
    assert out.steeringAngle == pytest.approx(0.3)      # float32 in the message


def test_joint_state_from_an_isaac_read_joint_state_reading_is_converted_as_isaacs_writer_converts_it():
    """Isaac Sim 6's preferred path: the reading's arrays, prismatic values x 1/metersPerUnit, revolute efforts
    x 1/metersPerUnit^2, every value rounded to 1e-4, stamped with sensorTime when it is positive."""
    reading = {"jointNames": ["shoulder", "slider"], "jointPositions": [0.123456, 0.3], "jointVelocities": [-1.0, 0.25],
               "jointEfforts": [2.0, 4.0], "jointDofTypes": [0, 1], "stageMetersPerUnit": 0.5, "sensorTime": 2.5,
               "timeStamp": 9.0}
    node = NodeHarness(BRIDGE + "ROS2PublishJointState", reading)
    node.compute("execIn")
    (topic, type_name, message), = _published(node.world)
    assert (topic, type_name) == ("/joint_states", "sensor_msgs/msg/JointState")
    assert message["header"]["stamp"] == {"sec": 2, "nanosec": 500_000_000}
    assert message["name"] == ["shoulder", "slider"]
    assert message["position"] == [0.1235, 0.6] and message["velocity"] == [-1.0, 0.5]
    assert message["effort"] == [8.0, 8.0]


def test_joint_state_refuses_a_reading_whose_arrays_disagree_or_nothing_to_publish():
    node = NodeHarness(BRIDGE + "ROS2PublishJointState", {"jointNames": ["a", "b"], "jointPositions": [0.0],
                                                          "jointVelocities": [0.0, 0.0], "jointEfforts": [0.0, 0.0],
                                                          "jointDofTypes": [0, 0], "stageMetersPerUnit": 1.0})
    with pytest.raises(GraphRuntimeError, match="one entry per joint .*2 names, 1 positions"):
        node.compute("execIn")
    with pytest.raises(GraphRuntimeError, match="no Isaac Read Joint State arrays are connected"):
        NodeHarness(BRIDGE + "ROS2PublishJointState", {}).compute("execIn")


def test_a_message_field_reads_nested_and_array_fields_and_names_a_missing_one():
    """graphflow.ROS2MessageField: Kit's field output names ('data', 'header:stamp:sec') on the JSON message."""
    message = json.dumps({"header": {"stamp": {"sec": 3, "nanosec": 5}, "frame_id": "odom"}, "data": [1.0, 2.5]})
    nested = NodeHarness("graphflow.ROS2MessageField", {"message": message, "field": "header:stamp:sec"})
    assert nested.compute().outputs["value"] == 3
    array = NodeHarness("graphflow.ROS2MessageField", {"message": message, "field": "data"})
    assert array.compute().outputs["value"] == (1.0, 2.5)
    with pytest.raises(GraphRuntimeError, match="no field 'seq' .*fields: frame_id, stamp"):
        NodeHarness("graphflow.ROS2MessageField", {"message": message, "field": "header:seq"}).compute()


def test_generic_subscriber_holds_the_types_defaults_until_the_first_message():
    """As Kit's per-field outputs hold their defaults: std_msgs/Float32 data 0.0, execOut not fired."""
    node = NodeHarness(BRIDGE + "ROS2Subscriber", {"topicName": "/pan", "messageName": "Float32"})
    assert node.tick("execIn").fired == set()
    assert json.loads(node.outputs.message) == {"data": 0.0}
