"""Issue 26 item 5: randomization and sweep files report every problem at once, each with its real reason."""
import json
import subprocess
import sys

from conftest import GRAPHS

from graphflow import cli

TUNED = GRAPHS / "ur10_pick_place_tuned.json"     # a graphflow.LegacySurfaceGripper named 'gripper'
UNKNOWN = "unknown distribution 'gaussian' (one of uniform, normal, logUniform, choice, with an optional clip)"


def run_cli(capsys, *args):
    code = cli.main([str(a) for a in args])
    out, err = capsys.readouterr()
    return code, out, err


def clean_lines(err: str) -> list[str]:
    assert "unexpected error" not in err and "Traceback" not in err
    return err.splitlines()


def write(path, data) -> str:
    path.write_text(json.dumps(data), encoding="utf-8")
    return str(path)


def test_an_unknown_distribution_is_named_not_reported_as_a_missing_pose(tmp_path, capsys):
    path = write(tmp_path / "r.json", {"randomize": [{"set": "gripper.kd", "gaussian": [0, 1]}]})
    code, _out, err = run_cli(capsys, "run", TUNED, "--randomize", path)
    assert code == 2
    assert clean_lines(err) == [f"graphflow: error: {path}: randomize/0: {UNKNOWN}"]


def test_a_randomization_file_lists_every_problem_with_its_reason(tmp_path, capsys):
    entries = [
        {"set": "gripper.kd", "gaussian": [0, 1]},
        {"pose": "/World/Cube", "offset": {"wobble": [1, 2]}},
        {"set": "gripper.kd", "uniform": [2, 1]},
        {"neither": 1},
        {"set": "gripper.kd", "uniform": [1, 2], "normal": [1, 2]},
    ]
    path = write(tmp_path / "r.json", {"randomize": entries})
    code, _out, err = run_cli(capsys, "run", TUNED, "--randomize", path)
    assert code == 2
    assert sorted(clean_lines(err)) == sorted(f"graphflow: error: {path}: {line}" for line in [
        f"randomize/0: {UNKNOWN}",
        f"randomize/1/offset: {UNKNOWN.replace('gaussian', 'wobble')}",
        "randomize/2: uniform: low must not exceed high",
        "randomize/3: needs one of 'set', 'pose'",
        "randomize/4: gives 'uniform' and 'normal'; use only one of them",
    ])


def test_a_sweep_file_lists_schema_override_and_stage_problems_together(tmp_path, capsys):
    sweep = {"format": "graphflow-sweep", "formatVersion": [1, 0], "graph": str(TUNED),
             "grid": {"gripper.kp": [1.0, "abc"], "gripper.nosuch": [1], "/World/Nope.physics:mass": [1.0]},
             "randomize": [{"set": "gripper.kd", "gaussian": [0, 1]}, {"set": "gripper.kd", "uniform": [2, 1]}],
             "seeds": 0,
             "metrics": [{"name": "lost", "positionError": {"prim": "/World/NoCube", "target": [0, 0, 0]}}]}
    path = write(tmp_path / "s.json", sweep)
    code, _out, err = run_cli(capsys, "sweep", path, "--out", tmp_path / "results")
    assert code == 2
    assert sorted(clean_lines(err)) == sorted(f"graphflow: error: {path}: {line}" for line in [
        f"randomize/0: {UNKNOWN}",                                              # schema
        "seeds: 0 is less than the minimum of 1",                               # schema
        "randomize/1: uniform: low must not exceed high",                       # semantics
        "gripper.nosuch=1: node 'gripper' (graphflow.LegacySurfaceGripper) has no input 'nosuch'",
        'gripper.kp="abc": node \'gripper\' input \'kp\': expected double, got "abc"',
        "/World/Nope.physics:mass=1.0: the stage has no prim /World/Nope (did you mean '/World/Cube'?)",  # stage
        "metrics/0 (lost): the stage has no prim /World/NoCube",
    ])
    assert not (tmp_path / "results").exists()


# ---------------------------------------------------------------- 4. what --randomize drew

def test_run_randomize_logs_what_it_drew_and_the_trace_header_records_it(tmp_path):
    """The drawn values follow from the documented streams: ``random.Random("graphflow:SEED:INDEX")``."""
    import random
    from statistics import NormalDist

    entries = [{"set": "gripper.kd", "uniform": [50, 150]},
               {"pose": "/World/Cube", "offset": {"uniform": [[-0.01, -0.01, 0], [0.01, 0.01, 0]]},
                "yawDegrees": {"normal": [0, 5]}}]
    path = write(tmp_path / "r.json", {"randomize": entries})
    trace = tmp_path / "run.jsonl"
    done = subprocess.run([sys.executable, "-m", "graphflow", "run", str(TUNED), "--randomize", path, "--seed", "3",
                           "--ticks", "2", "--log-level", "info", "--trace", str(trace)],
                          capture_output=True, text=True, check=False)
    assert done.returncode == 0, done.stderr
    err = done.stderr
    first, second = random.Random("graphflow:3:0"), random.Random("graphflow:3:1")
    kd = 50 + 100 * first.random()
    offset = [-0.01 + 0.02 * second.random(), -0.01 + 0.02 * second.random(), 0.0 * second.random()]
    yaw = 5 * NormalDist().inv_cdf(second.random())
    expected = [{"set": "gripper.kd", "value": kd}, {"pose": "/World/Cube", "offset": offset, "yawDegrees": yaw}]
    drawn_lines = [line for line in clean_lines(err) if "drew" in line]
    assert drawn_lines == [f"INFO graphflow.randomize: {path}: seed 3 drew {json.dumps(record)}" for record in expected]
    header = json.loads(trace.read_text(encoding="utf-8").splitlines()[0])
    assert header["randomized"] == expected


def test_a_trace_without_randomize_has_no_randomized_field(tmp_path, capsys):
    trace = tmp_path / "run.jsonl"
    assert run_cli(capsys, "run", TUNED, "--ticks", "1", "--trace", trace)[0] == 0
    assert "randomized" not in json.loads(trace.read_text(encoding="utf-8").splitlines()[0])


# ---------------------------------------------------------------- 11. a folder where a file is written

def test_test_with_a_junit_folder_is_bad_usage_before_any_scenario_runs(tmp_path, capsys):
    folder = tmp_path / "reports"
    folder.mkdir()
    code, out, err = run_cli(capsys, "test", GRAPHS / "scenarios", "--junit", folder, "--force")
    assert code == 2
    assert out == ""                                     # no scenario line: nothing ran
    assert clean_lines(err) == [f"graphflow: error: {folder}: is a folder, not a file"]
    assert list(folder.iterdir()) == []


def test_other_file_outputs_given_a_folder_are_refused_before_work(tmp_path, capsys):
    folder = tmp_path / "out"
    folder.mkdir()
    for command in (["run", GRAPHS / "counter_branch_print.json", "--trace", folder, "--force"],
                    ["nodes", "--markdown", "-o", folder, "--force"]):
        code, out, err = run_cli(capsys, *command)
        assert code == 2 and out == ""
        assert clean_lines(err) == [f"graphflow: error: {folder}: is a folder, not a file"]


def test_a_sweep_of_endless_episodes_is_refused_like_run_seconds(tmp_path, capsys):
    """``"seconds": 1e308`` ran until each episode's graph stopped itself; ``run --seconds`` stops at 1e7."""
    path = write(tmp_path / "s.json", {"format": "graphflow-sweep", "formatVersion": [1, 0], "graph": str(TUNED),
                                       "seconds": 1e308, "seeds": 1})
    code, _out, err = run_cli(capsys, "sweep", path, "--out", tmp_path / "results")
    assert code == 2
    assert clean_lines(err) == [f"graphflow: error: {path}: seconds: 1e+308 is greater than the maximum of 10000000"]
