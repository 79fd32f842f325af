"""The progress line: simulated time, ticks per second and the controller's phase on a terminal; quiet otherwise."""
import subprocess
import sys

from conftest import ROOT

from graphflow.observe.terminal import Progress
from graphflow.testing import GraphHarness


def test_status_shows_time_rate_and_the_phase_of_a_node_with_an_event_name():
    harness = GraphHarness({"settings": {"timeStep": 0.5}, "nodes": [{"name": "tick", "type": "omni.graph.action.OnTick"}]})
    harness.run(4)
    line = Progress(harness.simulation, enabled=True).status(4, 10, elapsed=2.0)
    assert "t =    2.000 s" in line and "tick 4/10" in line and "2 ticks/s" in line
    assert "phase" not in line                                    # no controller in this graph


def test_phase_comes_from_the_controller_output(monkeypatch):
    harness = GraphHarness({"nodes": [{"name": "tick", "type": "omni.graph.action.OnTick"}]})
    progress = Progress(harness.simulation, enabled=True)
    progress.phase_node = "tick"
    monkeypatch.setattr(harness.instance, "output", lambda node, name: "lift" if (node, name) == ("tick", "eventName") else None)
    assert "phase lift" in progress.status(1, None, elapsed=1.0)


def test_a_run_piped_to_a_file_prints_no_progress_line():
    result = subprocess.run([sys.executable, "-m", "graphflow", "run", str(ROOT / "graphs" / "counter_branch_print.json")],
                            capture_output=True, text=True)
    assert "ticks/s" not in result.stderr and "\r" not in result.stderr
