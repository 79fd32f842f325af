"""graphflow run's verdict and exit codes, graphflow test (lines, JUnit XML, kept traces) and the pytest plugin."""
import json
import subprocess
import sys
from pathlib import Path

import pytest

from graphflow.executor import GraphRuntimeError
from graphflow.testing import ExecState, NodeHarness


def graphflow(*args, cwd=None):
    return subprocess.run([sys.executable, "-m", "graphflow", *args], capture_output=True, text=True, cwd=cwd)


def _counter_graph(stop_at, checks, assert_below=None, **extra):
    """Counts ticks of 0.5 s and stops at *stop_at*; optionally Asserts the count stays below *assert_below*."""
    nodes = [{"name": "tick", "type": "omni.graph.action.OnTick"},
             {"name": "counter", "type": "omni.graph.action.Counter"},
             {"name": "enough", "type": "omni.graph.nodes.Compare", "inputs": {"b": stop_at, "operation": ">="}},
             {"name": "branch", "type": "omni.graph.action.Branch"},
             {"name": "stop", "type": "graphflow.StopRun"}]
    connections = [{"src": "tick.outputs:tick", "dst": "counter.inputs:execIn"},
                   {"src": "counter.outputs:count", "dst": "enough.inputs:a"},
                   {"src": "counter.outputs:execOut", "dst": "branch.inputs:execIn"},
                   {"src": "enough.outputs:result", "dst": "branch.inputs:condition"},
                   {"src": "branch.outputs:execTrue", "dst": "stop.inputs:execIn"}]
    if assert_below is not None:
        nodes += [{"name": "small", "type": "omni.graph.nodes.Compare", "inputs": {"b": assert_below, "operation": "<"}},
                  {"name": "count_is_small", "type": "graphflow.Assert", "inputs": {"message": "the count stays small"}}]
        connections += [{"src": "counter.outputs:count", "dst": "small.inputs:a"},
                        {"src": "small.outputs:result", "dst": "count_is_small.inputs:condition"},
                        {"src": "branch.outputs:execFalse", "dst": "count_is_small.inputs:execIn"}]
    return {"format": "graphflow", "formatVersion": [1, 0], "settings": {"timeStep": 0.5, "duration": 10.0},
            "nodes": nodes, "connections": connections, "checks": checks, **extra}


def _write(folder, name, graph):
    path = folder / name
    path.write_text(json.dumps(graph))
    return path


def test_assert_fires_exec_out_when_true_and_fails_naming_tick_time_and_message_when_false():
    node = NodeHarness("graphflow.Assert", inputs={"condition": True, "message": "gripper Closed after the lift"})
    assert "execOut" in node.compute("execIn").fired
    node.set_inputs(condition=False)
    with pytest.raises(GraphRuntimeError) as error:
        node.compute("execIn")
    assert str(error.value).startswith("node 'node': assertion failed at tick ")
    assert str(error.value).endswith("s: gripper Closed after the lift")
    assert node.compute().exec_states.get("execOut", ExecState.DISABLED) == ExecState.DISABLED   # no pulse: no check


def test_run_exits_0_when_every_check_holds_and_1_with_one_line_per_failed_check(tmp_path):
    passing = _write(tmp_path, "passing.json", _counter_graph(3, [{"check": "stopsBy", "time": 2.0}]))
    result = graphflow("run", str(passing))
    assert result.returncode == 0, result.stderr
    assert result.stderr.splitlines() == [f"graphflow: PASS {passing}: 1 check holds (3 ticks, 1.500 s simulated)"]

    late = _write(tmp_path, "late.json", _counter_graph(6, [{"check": "stopsBy", "time": 2.0}, {"check": "finite"}]))
    result = graphflow("run", str(late))
    assert result.returncode == 1
    assert result.stderr.splitlines() == [
        f"{late}: check 1 'graph stops by itself by 2 s': measured still running when the run ended at t = 2.000 s; "
        "expected the graph stops by itself (StopRun) by t = 2 s",
        f"graphflow: FAIL {late}: 1 failure (4 ticks, 2.000 s simulated)"]


def test_a_false_assert_exits_1_naming_node_tick_time_and_message(tmp_path):
    graph = _write(tmp_path, "asserting.json", _counter_graph(6, [{"check": "stopsBy", "time": 5.0}], assert_below=3))
    result = graphflow("run", str(graph))
    assert result.returncode == 1
    assert result.stderr.splitlines() == [
        f"{graph}: run-time failure: node 'count_is_small': assertion failed at tick 3, t = 1.500 s: the count stays small",
        f"graphflow: FAIL {graph}: 1 failure (3 ticks, 1.500 s simulated)"]


def test_a_run_changed_by_limits_or_inputs_skips_the_checks_unless_asked(tmp_path):
    graph = _write(tmp_path, "g.json", _counter_graph(3, [{"check": "stopsBy", "time": 2.0}]))
    result = graphflow("run", str(graph), "--ticks", "2")
    assert result.returncode == 0
    assert "checks not evaluated, --ticks changed the run" in result.stderr
    assert graphflow("run", str(graph), "--ticks", "2", "--checks").returncode == 1


def test_graphflow_test_lines_last_line_junit_and_kept_trace(tmp_path):
    from junitparser import Error, Failure, JUnitXml

    folder = tmp_path / "scenarios"
    (folder / "nested").mkdir(parents=True)
    passing = _write(folder, "a_passing.json", _counter_graph(3, [{"check": "stopsBy", "time": 2.0}]))
    failing = _write(folder / "nested", "b_failing.json", _counter_graph(6, [{"check": "stopsBy", "time": 2.0}]))
    _write(folder, "no_checks.json", {**_counter_graph(3, []), "checks": []})          # not a scenario
    expected_failure = _write(folder, "c_shows_a_failure.json", _counter_graph(
        6, [{"check": "stopsBy", "time": 2.0}], scenario={"expectFailure": ["still running"]}))
    (folder / "broken.json").write_text('{"format": "graphflow", "checks": [1]}')   # a scenario that does not load
    report = tmp_path / "report.xml"
    result = graphflow("test", str(folder), "--junit", str(report), "-j", "2", "--traces", str(tmp_path / "traces"))
    lines = result.stdout.splitlines()
    assert result.returncode == 2, result.stderr                                    # a bad scenario is bad input
    assert lines[0] == f"PASS {passing}: 1 check holds (3 ticks, 1.500 s simulated)"
    assert lines[1].startswith(f"ERROR {folder / 'broken.json'}: ")
    assert lines[2] == f"XFAIL {expected_failure}: failed as expected (4 ticks, 2.000 s simulated)"
    failing_at = lines.index(f"FAIL {failing}: 1 failure (4 ticks, 2.000 s simulated)")
    trace_line, timeline_line, rerun_line = lines[failing_at + 2: failing_at + 5]
    assert trace_line.startswith("    trace: ") and Path(trace_line.split(": ", 1)[1]).is_file()
    assert timeline_line == f"    timeline: {tmp_path / 'traces' / '003-b_failing.png'}"
    assert rerun_line == f"    re-run: graphflow run {failing}"
    assert lines[-1] == "2 passed, 2 failed"
    assert sorted(p.name for p in (tmp_path / "traces").iterdir()) == ["003-b_failing.jsonl", "003-b_failing.png"]

    suite = next(iter(JUnitXml.fromfile(str(report))))
    assert (suite.tests, suite.failures, suite.errors) == (4, 1, 1)
    cases = {case.name: case for case in suite}
    assert cases["a_passing.json"].is_passed and cases["c_shows_a_failure.json"].is_passed
    (failure,) = cases["b_failing.json"].result
    assert isinstance(failure, Failure) and "still running when the run ended" in failure.text
    assert isinstance(cases["broken.json"].result[0], Error)

    again = graphflow("test", str(passing), "--junit", str(report))
    assert again.returncode == 2 and "already exists; not overwriting it (use --force)" in again.stderr
    assert graphflow("test", str(passing), "--junit", str(report), "--force").returncode == 0
    assert next(iter(JUnitXml.fromfile(str(report)))).tests == 1


def test_graphflow_test_without_scenarios_is_bad_input(tmp_path):
    result = graphflow("test", str(tmp_path))
    assert result.returncode == 2
    assert result.stderr.strip() == f"graphflow: error: no graph with checks under {tmp_path}"


def test_pytest_plugin_is_opt_in_and_shows_the_failed_checks(tmp_path):
    _write(tmp_path, "good.json", _counter_graph(3, [{"check": "stopsBy", "time": 2.0}]))
    _write(tmp_path, "late.json", _counter_graph(6, [{"check": "stopsBy", "time": 2.0}]))
    command = [sys.executable, "-m", "pytest", "-p", "no:cacheprovider", "-q", str(tmp_path)]
    off = subprocess.run(command, capture_output=True, text=True, cwd=tmp_path)
    assert "no tests ran" in off.stdout                       # not configured: JSON files are not collected
    on = subprocess.run(command + ["--graphflow-scenarios"], capture_output=True, text=True, cwd=tmp_path)
    assert on.returncode == 1
    assert "1 failed, 1 passed" in on.stdout
    assert "check 1 'graph stops by itself by 2 s': measured still running when the run ended at t = 2.000 s" in on.stdout
    assert "re-run: graphflow run" in on.stdout
