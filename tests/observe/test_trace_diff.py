"""graphflow trace diff: the first tick and field where two runs part (exit 0 same, 1 different, 2 bad input)."""
import json
import subprocess
import sys
from pathlib import Path

from conftest import ROOT

from graphflow.observe.trace import first_difference, read_trace

COUNTER_GRAPH = ROOT / "graphs" / "counter_branch_print.json"


def graphflow(*args):
    return subprocess.run([sys.executable, "-m", "graphflow", *args], capture_output=True, text=True)


def counter_trace(tmp_path, name):
    path = tmp_path / name
    assert graphflow("run", str(COUNTER_GRAPH), "--trace", str(path)).returncode == 0
    return path


def edited(source: Path, target: Path, tick: int, edit) -> Path:
    lines = source.read_text().splitlines()
    record = json.loads(lines[tick])
    edit(record)
    lines[tick] = json.dumps(record, separators=(",", ":"))
    target.write_text("\n".join(lines) + "\n")
    return target


def test_identical_runs_exit_0(tmp_path):
    result = graphflow("trace", "diff", str(counter_trace(tmp_path, "a.jsonl")), str(counter_trace(tmp_path, "b.jsonl")))
    assert result.returncode == 0
    assert result.stdout == "traces are identical (3 ticks)\n"


def test_an_injected_output_change_is_found_at_its_tick_and_field(tmp_path):
    original = counter_trace(tmp_path, "a.jsonl")
    changed = edited(original, tmp_path / "b.jsonl", 2, lambda r: r["outputs"].update({"counter.count": 7}))
    result = graphflow("trace", "diff", str(original), str(changed))
    assert result.returncode == 1
    assert result.stdout.splitlines() == [
        "traces differ at tick 2 (t = 1.0 s), field outputs.counter.count:",
        f"  {original}: 2", f"  {changed}: 7"]


def test_a_changed_pulse_is_named_by_its_position(tmp_path):
    original = counter_trace(tmp_path, "a.jsonl")
    changed = edited(original, tmp_path / "b.jsonl", 3, lambda r: r["pulses"].__setitem__(2, "branch.execFalse"))
    difference = first_difference(read_trace(original), read_trace(changed))
    assert (difference.tick, difference.field) == (3, "pulses[2]")
    assert (difference.left, difference.right) == ("branch.execTrue", "branch.execFalse")


def test_a_missing_field_and_a_shorter_trace_are_differences(tmp_path):
    original = counter_trace(tmp_path, "a.jsonl")
    without_log = edited(original, tmp_path / "b.jsonl", 1, lambda r: r.pop("log"))
    difference = first_difference(read_trace(original), read_trace(without_log))
    assert (difference.tick, difference.field) == (1, "log")
    shorter = tmp_path / "c.jsonl"
    shorter.write_text("".join(original.read_text().splitlines(keepends=True)[:3]))
    difference = first_difference(read_trace(original), read_trace(shorter))
    assert (difference.tick, difference.field, difference.left, difference.right) == (3, "tick", 3, "<absent>")


def test_other_versions_are_not_a_difference_but_another_graph_is(tmp_path):
    original = counter_trace(tmp_path, "a.jsonl")
    other_python = edited(original, tmp_path / "b.jsonl", 0, lambda r: r["versions"].update({"python": "9.9"}))
    assert first_difference(read_trace(original), read_trace(other_python)) is None
    other_step = edited(original, tmp_path / "c.jsonl", 0, lambda r: r.update({"timeStep": 0.25}))
    difference = first_difference(read_trace(original), read_trace(other_step))
    assert (difference.tick, difference.field) == (0, "timeStep")


def test_an_int_and_a_float_of_equal_value_differ(tmp_path):
    original = counter_trace(tmp_path, "a.jsonl")
    floated = edited(original, tmp_path / "b.jsonl", 1, lambda r: r["outputs"].update({"counter.count": 1.0}))
    assert first_difference(read_trace(original), read_trace(floated)).field == "outputs.counter.count"


def test_bad_input_exits_2(tmp_path):
    original = counter_trace(tmp_path, "a.jsonl")
    not_a_trace = tmp_path / "graph.jsonl"
    not_a_trace.write_text('{"format": "graphflow"}\n')
    for other in (tmp_path / "missing.jsonl", not_a_trace, COUNTER_GRAPH):
        result = graphflow("trace", "diff", str(original), str(other))
        assert result.returncode == 2, other
        assert result.stderr.startswith(f"graphflow: error: {other}: ") and "Traceback" not in result.stderr
