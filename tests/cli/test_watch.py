"""`graphflow run --watch` and `graphflow test --watch`: a verdict per run, a bad edit said and watched past, Ctrl-C exits 130.

The watch's polls are driven by the test (graphflow.watching.Watcher's injectable sleep): each poll
makes the next real edit in tmp_path, and the end of the script is a Ctrl-C.
"""
import functools
import json
import shutil

import pytest
from conftest import GRAPHS
from polls import Script

from graphflow import watching
from graphflow.cli import main


@pytest.fixture
def counter(tmp_path, monkeypatch):
    """A copy of the counter scenario, in the current folder (the watch names changed files relative to it)."""
    shutil.copy(GRAPHS / "counter_branch_print.json", tmp_path / "counter.json")
    monkeypatch.chdir(tmp_path)
    return tmp_path / "counter.json"


def with_stops_by(graph, seconds):
    """The counter stops by itself at 1.5 s (tick 3 of 0.5 s): a stopsBy check of *seconds* holds from 1.5 s on."""
    data = json.loads(graph.read_text())
    data["checks"][0]["time"] = seconds
    return lambda: graph.write_text(json.dumps(data, indent=2))


def watched(monkeypatch, script):
    monkeypatch.setattr(watching, "Watcher", functools.partial(watching.Watcher, sleep=script))


def test_run_watch_runs_again_once_per_edit_says_a_bad_edit_and_exits_130_on_ctrl_c(counter, monkeypatch, capsys):
    script = Script(None, with_stops_by(counter, 1.0), None, None,            # run 2: the check fails
                    lambda: counter.write_text('{"nodes": ['), None, None,    # run 3: not JSON
                    with_stops_by(counter, 2.5), None, None)                  # run 4: holds again
    watched(monkeypatch, script)
    assert main(["run", "counter.json", "--watch"]) == 130
    err = capsys.readouterr().err
    banners = [line for line in err.splitlines() if line.startswith("========")]
    assert [line.split(": ", 1)[1] for line in banners[::2]] == [
        "run 1 (first run) ========", "run 2 (changed: counter.json) ========", "run 3 (changed: counter.json) ========",
        "run 4 (changed: counter.json) ========"]
    verdicts = [line.split(": ", 1)[1].split(";")[0] for line in banners[1::2]]
    assert verdicts == ["run 1 passed (exit 0)", "run 2 failed (exit 1)", "run 3 bad input (exit 2)", "run 4 passed (exit 0)"]
    run_3 = err.split("run 3 (changed", 1)[1].split("run 3 bad input", 1)[0]
    errors = [line for line in run_3.splitlines() if line.startswith("graphflow: error:")]
    assert len(errors) == 1 and "counter.json" in errors[0]   # one line naming the file, no traceback
    assert "Traceback" not in err
    assert err.count("graphflow: FAIL") == 1 and err.count("graphflow: PASS") == 2
    assert err.rstrip().endswith("graphflow: interrupted")


def test_test_watch_picks_up_a_new_scenario_in_the_folder(counter, monkeypatch, capsys):
    second = counter.parent / "again.json"
    watched(monkeypatch, Script(lambda: shutil.copy(counter, second), None, None))
    assert main(["test", str(counter.parent), "--watch", "-j", "1"]) == 130
    out = capsys.readouterr()
    assert [line for line in out.out.splitlines() if "passed," in line] == ["1 passed, 0 failed", "2 passed, 0 failed"]
    assert "run 2 (changed: " in out.err and "again.json" in out.err


def test_run_watch_replaces_the_trace_its_previous_run_wrote(counter, monkeypatch, capsys):
    trace = counter.parent / "counter.jsonl"
    watched(monkeypatch, Script(with_stops_by(counter, 2.5), None, None))
    assert main(["run", str(counter), "--watch", "--trace", str(trace)]) == 130
    err = capsys.readouterr().err
    assert "run 2 passed (exit 0)" in err and "already exists" not in err
    assert trace.read_text().count("\n") == 4   # the header and 3 ticks, written again by run 2
