"""Runs shared by the report tests: each shipped graph is run once per session, with a trace and a report."""
import subprocess
import sys
from pathlib import Path

import pytest

GRAPHS = Path(__file__).resolve().parents[2] / "graphs"   # (this file is itself a conftest: no import of tests/conftest)

PICK_PLACE = GRAPHS / "ur10_pick_place.json"
PICK_MISSES = GRAPHS / "scenarios" / "pick_misses.json"


def graphflow(*args, cwd=None):
    return subprocess.run([sys.executable, "-m", "graphflow", *args], capture_output=True, text=True, cwd=cwd)


def _run(folder, graph):
    trace, report = folder / f"{graph.stem}.jsonl", folder / f"{graph.stem}.html"
    result = graphflow("run", str(graph), "--trace", str(trace), "--report", str(report))
    return {"result": result, "trace": trace, "report": report}


@pytest.fixture(scope="session")
def pick_place_run(tmp_path_factory):
    run = _run(tmp_path_factory.mktemp("pick_place"), PICK_PLACE)
    assert run["result"].returncode == 0, run["result"].stderr
    return run


@pytest.fixture(scope="session")
def pick_misses_run(tmp_path_factory):
    run = _run(tmp_path_factory.mktemp("pick_misses"), PICK_MISSES)
    assert run["result"].returncode == 1, run["result"].stderr
    return run
