"""A ROS 2 joint-state graph from the Isaac corpus, headless: scripted /joint commands in, MCAP out.

The corpus's UFactory Lite6 graph (ros_joint_states.usda) is a layer its
author sublayers into the robot asset, so its robot targets are empty; as a
user would, the test points them at graphflow's packaged UR10 and runs it with
``graphflow run --topics ... --record-topics ...``. The recording is read
back with the ``mcap`` reader and ``mcap-ros2-support``'s CDR decoder.
"""
import json
import math
from pathlib import Path

import pytest

pytest.importorskip("rosbags")
mcap_reader = pytest.importorskip("mcap.reader")
mcap_ros2_decoder = pytest.importorskip("mcap_ros2.decoder")

from conftest import CORPUS_FILES as CORPUS
from conftest import GRAPHS

from graphflow.cli import main  # noqa: E402

LITE6_GRAPH = CORPUS / "pastoriomarco__isaac_sim_custom_examples" / "ros_joint_states.usda"
UR10_JOINTS = ["shoulder_pan_joint", "shoulder_lift_joint", "elbow_joint",
               "wrist_1_joint", "wrist_2_joint", "wrist_3_joint"]
HALF_PI = math.pi / 2
COMMAND = {"name": ["shoulder_pan_joint", "elbow_joint"], "position": [0.5, -0.3]}

needs_corpus = pytest.mark.skipif(not LITE6_GRAPH.is_file(), reason="../shared/isaac_corpus is absent")


def _graph_on_ur10(tmp_path) -> Path:
    graph = tmp_path / "lite6.json"
    assert main(["import", str(LITE6_GRAPH), "-o", str(graph)]) == 0
    document = json.loads(graph.read_text())
    document["settings"]["stage"] = "asset:ur10.usda"
    for node in document["nodes"]:
        if node["name"] in ("PublisherJointState", "ArticulationController", "ArticulationControllerGripper"):
            node.setdefault("inputs", {})["targetPrim"] = ["/ur10"]
    graph.write_text(json.dumps(document))
    return graph


def _read(path: Path) -> list:
    with path.open("rb") as stream:
        reader = mcap_reader.make_reader(stream, decoder_factories=[mcap_ros2_decoder.DecoderFactory()])
        assert reader.get_header().profile == "ros2"
        return [(channel.topic, schema.name, message.log_time, decoded)
                for schema, channel, message, decoded in reader.iter_decoded_messages()]


@needs_corpus
def test_scripted_joint_command_moves_the_arm_and_the_mcap_holds_the_joint_states(tmp_path):
    graph = _graph_on_ur10(tmp_path)
    topics = tmp_path / "commands.json"
    topics.write_text(json.dumps({"topics": [
        {"topic": "/isaac_joint_commands", "time": 0.1, "type": "sensor_msgs/msg/JointState", "message": COMMAND}]}))
    recording = tmp_path / "run.mcap"
    assert main(["run", str(graph), "--ticks", "120", "--topics", str(topics),
                 "--record-topics", str(recording)]) == 0

    messages = _read(recording)
    assert len(messages) == 120   # one JointState per tick
    assert {(topic, schema) for topic, schema, _, _ in messages} == {("/isaac_joint_states", "sensor_msgs/msg/JointState")}
    for tick, (_, _, log_time, state) in enumerate(messages, start=1):
        assert list(state.name) == UR10_JOINTS
        stamp_ns = state.header.stamp.sec * 1_000_000_000 + state.header.stamp.nanosec
        assert stamp_ns == log_time == round(tick / 60 * 1e9)   # ReadSimTime -> stamp: simulated seconds
    first, last = messages[0][3], messages[-1][3]
    home = [-HALF_PI, -HALF_PI, -HALF_PI, -HALF_PI, HALF_PI, 0.0]   # the packaged UR10's drive targets
    assert list(first.position) == pytest.approx(home, abs=1e-3)
    # the command (t = 0.1 s) moved the two joints it names, within 2 s, and left the others where they were
    assert list(last.position) == pytest.approx([0.5, -HALF_PI, -0.3, -HALF_PI, HALF_PI, 0.0], abs=2e-3)
    moving = [state.position[0] for _, _, _, state in messages]
    assert moving[5] == pytest.approx(-HALF_PI, abs=1e-3) and moving[30] > -HALF_PI + 0.1


@needs_corpus
def test_command_on_the_command_line_and_trace_records_published_messages(tmp_path):
    graph = _graph_on_ur10(tmp_path)
    trace = tmp_path / "run.jsonl"
    assert main(["run", str(graph), "--ticks", "30", "--trace", str(trace),
                 "--topic", '/isaac_joint_commands@0.2={"name": ["wrist_3_joint"], "position": [1.0]}']) == 0
    records = [json.loads(line) for line in trace.read_text().splitlines()[1:]]
    published = [record["topics"] for record in records]
    assert all(len(tick) == 1 and tick[0]["topic"] == "/isaac_joint_states" for tick in published)
    last = published[-1][0]["message"]
    assert last["name"] == UR10_JOINTS and last["position"][5] > 0.3   # the wrist turns towards 1 rad


@needs_corpus
def test_recording_never_overwrites(tmp_path, capsys):
    graph = _graph_on_ur10(tmp_path)
    recording = tmp_path / "run.mcap"
    recording.write_bytes(b"keep")
    assert main(["run", str(graph), "--ticks", "1", "--record-topics", str(recording)]) == 2
    assert "already exists" in capsys.readouterr().err
    assert recording.read_bytes() == b"keep"


def test_shipped_joint_state_graph_publishes_clock_and_follows_its_timeline(tmp_path):
    root = GRAPHS
    recording = tmp_path / "run.mcap"
    assert main(["run", str(root / "ros2_joint_states.json"), "--topics", str(root / "ros2_joint_states.topics.json"),
                 "--record-topics", str(recording)]) == 0
    messages = _read(recording)
    clocks = [(log_time, clock.clock) for topic, _, log_time, clock in messages if topic == "/clock"]
    states = [state for topic, _, _, state in messages if topic == "/joint_states"]
    assert len(clocks) == len(states) == 180   # 3 s at 60 Hz
    assert all(log_time == clock.sec * 1_000_000_000 + clock.nanosec for log_time, clock in clocks)
    assert clocks[-1][1].sec == 3 and clocks[-1][1].nanosec == 0
    at_1_4_s = states[83]   # tick 84: the first command (0.5 s) has had 0.9 s
    assert at_1_4_s.position[0] == pytest.approx(-0.5, abs=0.01) and at_1_4_s.position[2] == pytest.approx(-1.2, abs=0.01)
    assert list(states[-1].position[:3]) == pytest.approx([-HALF_PI] * 3, abs=0.01)   # back home after the second
