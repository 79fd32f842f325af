"""Issue 26 item 5: one rule for every scripted input, and ``scenario.topics`` in run, test and sweeps alike.

The rule: the graph's ``scenario`` section is the input its checks were written for. A scripted input
given on the command line (``--key(s)``, ``--gamepad``/``--pad``, ``--topic(s)``) replaces it, so the run
is not the one the checks judge: they are suspended (``--checks`` evaluates them anyway).
"""
import json
import math

from conftest import GRAPHS

from graphflow import cli

ROS_GRAPH = GRAPHS / "ros2_joint_states.json"
PAN = -0.5     # the shoulder pan the scripted message commands (rad); the UR10 starts at -pi/2
COMMAND = '/joint_command@0.5={"name": ["shoulder_pan_joint"], "position": [%s]}' % PAN


def run_cli(capsys, *args):
    code = cli.main([str(a) for a in args])
    out, err = capsys.readouterr()
    assert "unexpected error" not in err and "Traceback" not in err
    return code, out, err


def panned_graph(tmp_path, topics) -> str:
    """The ROS 2 bridge graph whose check is the end effector turned by the pan command about the base's Z axis.

    Only the pan joint moves, so the reference is the start position rotated by (PAN + pi/2): same height,
    same distance from the axis (the arm's base is at the origin).
    """
    data = json.loads(ROS_GRAPH.read_text(encoding="utf-8"))
    data["settings"]["stage"] = str(GRAPHS.parent / "graphflow" / "assets" / "ur10.usda")
    x, y, z = data["checks"][0]["position"]        # where the arm's end effector starts (and stays, unscripted)
    turn = PAN + math.pi / 2
    data["checks"][0]["position"] = [x * math.cos(turn) - y * math.sin(turn), x * math.sin(turn) + y * math.cos(turn), z]
    data["checks"][0]["tolerance"] = 0.005
    data["scenario"] = {"topics": topics}
    path = tmp_path / "panned.json"
    path.write_text(json.dumps(data), encoding="utf-8")
    return str(path)


def test_scenario_topics_script_the_run_and_the_checks_judge_it(tmp_path, capsys):
    path = panned_graph(tmp_path, [COMMAND])
    code, _out, err = run_cli(capsys, "run", path)
    assert code == 0, err
    assert "PASS" in err and "2 checks hold" in err


def test_scenario_topics_as_objects_and_as_a_file_are_the_same_timeline(tmp_path, capsys):
    message = {"topic": "/joint_command", "time": 0.5, "type": "sensor_msgs/msg/JointState",
               "message": {"name": ["shoulder_pan_joint"], "position": [PAN]}}
    (tmp_path / "pan.topics.json").write_text(json.dumps({"topics": [message]}), encoding="utf-8")
    for topics in ([message], "pan.topics.json"):
        assert run_cli(capsys, "run", panned_graph(tmp_path, topics))[0] == 0


def test_without_the_scenario_the_same_check_fails(tmp_path, capsys):
    path = panned_graph(tmp_path, [COMMAND])
    data = json.loads(open(path, encoding="utf-8").read())
    del data["scenario"]
    (tmp_path / "unscripted.json").write_text(json.dumps(data), encoding="utf-8")
    code, _out, err = run_cli(capsys, "run", tmp_path / "unscripted.json")
    assert code == 1 and "position of /ur10/ee_link at the end" in err


def test_topic_options_suspend_the_checks_like_key_and_pad(tmp_path, capsys):
    path = panned_graph(tmp_path, [COMMAND])
    for option in (["--topic", COMMAND], ["--key", "A@1.0"], ["--pad", "Left Stick X Axis=0.5@1.0"]):
        code, _out, err = run_cli(capsys, "run", path, *option)
        assert code == 0
        assert f"checks not evaluated, {option[0]} changed the run (--checks evaluates them)" in err
    code, _out, err = run_cli(capsys, "run", path, "--topic", COMMAND, "--checks")
    assert code == 0 and "2 checks hold" in err           # the same message given as an option, judged


def test_graphflow_test_runs_the_scenario_topics(tmp_path, capsys):
    code, out, _err = run_cli(capsys, "test", panned_graph(tmp_path, [COMMAND]))
    assert code == 0 and "PASS" in out and "1 passed" in out


def test_a_sweep_episode_runs_the_scenario_topics(tmp_path, capsys):
    graph = panned_graph(tmp_path, [COMMAND])
    target = json.loads(open(graph, encoding="utf-8").read())["checks"][0]["position"]
    sweep = {"format": "graphflow-sweep", "formatVersion": [1, 0], "graph": graph, "seeds": 1,
             "metrics": [{"name": "off", "positionError": {"prim": "/ur10/ee_link", "target": target}}]}
    (tmp_path / "s.json").write_text(json.dumps(sweep), encoding="utf-8")
    code, _out, err = run_cli(capsys, "sweep", tmp_path / "s.json", "--out", tmp_path / "results", "-j", "1")
    assert code == 0, err
    (record,) = [json.loads(line) for line in (tmp_path / "results" / "episodes.jsonl").read_text().splitlines()]
    assert record["passed"] is True and record["failures"] == []     # the graph's checks held
    assert record["metrics"]["off"] < 0.005


def test_a_bad_scenario_topic_is_one_line_exit_2(tmp_path, capsys):
    path = panned_graph(tmp_path, [{"topic": "/joint_command", "time": -1, "message": {}}])
    code, _out, err = run_cli(capsys, "run", path)
    assert code == 2
    (line,) = err.splitlines()
    assert line == f"graphflow: error: {path}: scenario/topics/0: time must be a number of seconds >= 0, got -1"
