"""The shipped failing scenarios through graphflow run: exit 1, the gripper's reasons, the trace and the plot.

The passing ones run as test items of the pytest plugin (graphs/ is in testpaths)."""
import re
import subprocess
import sys

import pytest
from conftest import ROOT

SCENARIOS = ROOT / "graphs" / "scenarios"


def run(*args):
    return subprocess.run([sys.executable, "-m", "graphflow", "run", *map(str, args)], capture_output=True, text=True)


@pytest.mark.slow
def test_the_pick_that_misses_exits_1_with_the_grippers_reason_in_checks_trace_and_plot(tmp_path):
    from graphflow.observe.timeline import timeline
    from graphflow.observe.trace import read_trace

    trace = tmp_path / "miss.jsonl"
    result = run(SCENARIOS / "pick_misses.json", "--trace", trace)
    assert result.returncode == 1
    lines = result.stderr.splitlines()
    assert lines[-1].startswith(f"graphflow: FAIL {SCENARIOS / 'pick_misses.json'}: 2 failures (1127 ticks")
    held = next(line for line in lines if "holds /World/Cube" in line)
    assert ("measured holding nothing at t = 9.500 s (gripper Open: close failed: retry interval 1 s elapsed; "
            "/World/ur10/ee_link/attachment_joint: no surface within 0.0090 m (nearest hit /World/Cube at 0.023") in held
    assert any("565.7 mm from (0.7000, 0.7000, 0.0257)" in line for line in lines)   # never moved: 0.4 m x sqrt 2
    assert "WARNING: print_failure: the gripper never closed on an object: close failed" in result.stderr
    gripper = "/World/ur10/ee_link/SurfaceGripper"
    reasons = {reason for _, reason in read_trace(trace).gripper_series(gripper, "reason") if reason}
    assert len(reasons) == 1 and next(iter(reasons)).startswith("close failed: retry interval 1 s elapsed")
    node_reasons = {value for _, value in read_trace(trace).series("gripper.reason") if value}   # the node's output
    assert node_reasons == reasons
    status_panel = next(p for p in timeline(read_trace(trace)).panels if p.title == "gripper status")
    assert [text for _, _, text in status_panel.labels] == list(reasons)


@pytest.mark.slow
def test_the_heavy_cube_exits_1_with_the_measured_force_over_the_limit():
    result = run(SCENARIOS / "heavy_cube_breaks_grip.json")
    assert result.returncode == 1
    held = re.search(r"holds /World/Cube from 8.2 s to 16.8 s': measured holding nothing at t = 8.2\d\d s \(gripper Open: "
                     r"grip on /World/Cube broken by force ([\d.]+) N > limit 200 N at /World/ur10/ee_link/d6FixedJoint\)",
                     result.stderr)
    assert held, result.stderr
    weight = 30.0 * 9.81     # the cube's 294 N, plus what the lift's acceleration adds (measured 309-315 N)
    assert weight < float(held.group(1)) < 1.1 * weight

