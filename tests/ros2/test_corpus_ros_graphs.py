"""Corpus ROS 2 graphs as published: what they put on the bus, read back from the MCAP recording."""
import json
from pathlib import Path

import pytest

pytest.importorskip("rosbags")
mcap_reader = pytest.importorskip("mcap.reader")
mcap_ros2_decoder = pytest.importorskip("mcap_ros2.decoder")

from conftest import CORPUS_FILES as FILES

from graphflow.cli import main  # noqa: E402

pytestmark = pytest.mark.skipif(not FILES.is_dir(), reason="../shared/isaac_corpus is absent")


def _record(tmp_path, stage: Path, ticks: int):
    graph, recording = tmp_path / "graph.json", tmp_path / "run.mcap"
    assert main(["import", str(stage), "-o", str(graph)]) == 0
    assert main(["run", str(graph), "--ticks", str(ticks), "--record-topics", str(recording)]) == 0
    with recording.open("rb") as stream:
        reader = mcap_reader.make_reader(stream, decoder_factories=[mcap_ros2_decoder.DecoderFactory()])
        return [(channel.topic, schema.name, message.log_time, decoded)
                for schema, channel, message, decoded in reader.iter_decoded_messages()]


def test_hospital_clock_graph_publishes_simulated_time_on_clock(tmp_path):
    messages = _record(tmp_path, FILES / "Omotoye__isaac-projects" / "hospital_experiment.usda", 90)
    assert {(topic, schema) for topic, schema, _, _ in messages} == {("/clock", "rosgraph_msgs/msg/Clock")}
    assert len(messages) == 90
    assert all(log_time == clock.clock.sec * 1_000_000_000 + clock.clock.nanosec for _, _, log_time, clock in messages)
    assert (messages[-1][3].clock.sec, messages[-1][3].clock.nanosec) == (1, 500_000_000)


def test_rov_graph_publishes_every_standard_type_it_names_with_its_authored_fields(tmp_path):
    messages = _record(tmp_path, FILES / "IWIN-FINS__FinsSimIsaacLab" / "finsrov_ros2.usda", 2)
    last_tick = {topic: (schema, message) for topic, schema, log_time, message in messages if log_time == 33_333_333}
    assert {topic: schema for topic, (schema, _) in last_tick.items()} == {
        "/clock": "rosgraph_msgs/msg/Clock",
        "/sim/finsrov/controller/imu": "sensor_msgs/msg/Imu",
        "/sim/finsrov/ground_truth/odom": "nav_msgs/msg/Odometry",
        "/sim/finsrov/controller/pose": "geometry_msgs/msg/PoseWithCovarianceStamped",
        "/sim/finsrov/controller/depth": "geometry_msgs/msg/PoseWithCovarianceStamped",
        "/sim/finsrov/controller/dvl": "geometry_msgs/msg/TwistWithCovarianceStamped",
        "/sim/finsrov/bridge/status": "std_msgs/msg/String"}
    pose = last_tick["/sim/finsrov/controller/pose"][1]
    assert pose.header.frame_id == "controller_world"
    assert pose.pose.covariance[0] == pytest.approx(1e-6)   # the file's authored covariance, via messageFields
    odometry = last_tick["/sim/finsrov/ground_truth/odom"][1]
    assert (odometry.header.frame_id, odometry.child_frame_id) == ("controller_world", "finsrov/base_link")
    assert last_tick["/sim/finsrov/controller/imu"][1].header.frame_id == "finsrov/base_link"
    graph = json.loads((tmp_path / "graph.json").read_text())
    assert {node["name"] for node in graph["nodes"] if "messageFields" in node.get("inputs", {})} == {"Pose", "Depth", "Dvl"}
