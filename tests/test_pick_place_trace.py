"""The pick-and-place demo's trace tells its story: phases in order, the cube gripped, lifted and let go."""
import subprocess
import sys

import pytest
from conftest import ROOT

from graphflow.observe.trace import read_trace

PICK_PLACE = ROOT / "graphs" / "ur10_pick_place.json"
GRIPPER = "/World/ur10/ee_link/SurfaceGripper"

pytestmark = pytest.mark.slow


def traced(tmp_path, name):
    path = tmp_path / name
    result = subprocess.run([sys.executable, "-m", "graphflow", "run", str(PICK_PLACE), "--trace", str(path)],
                            capture_output=True, text=True)
    assert result.returncode == 0, result.stderr
    return path


def test_trace_records_phases_grip_height_and_release_and_is_reproducible(tmp_path):
    first, second = traced(tmp_path, "a.jsonl"), traced(tmp_path, "b.jsonl")
    assert first.read_bytes() == second.read_bytes()
    trace = read_trace(first)
    assert trace.header["phases"] == ["pick_place.eventName"]
    assert set(trace.header["versions"]) == {"graphflow", "python", "pybullet", "usd"}
    phases = [name for _, name in trace.series("pick_place.eventName")]
    assert phases.index("gripper_close") < phases.index("lift") < phases.index("gripper_open") < phases.index("done")

    status = [(t, s) for t, s in trace.gripper_series(GRIPPER, "status")]
    changes = [s for i, (_, s) in enumerate(status) if i == 0 or s != status[i - 1][1]]
    assert changes == ["Open", "Closed", "Open"]     # the cup stops above the cube, so the close grips at once
    gripped = {tuple(g) for _, g in trace.gripper_series(GRIPPER, "gripped") if g}
    assert gripped == {("/World/Cube",)}
    heights = [z for _, z in trace.gripper_series(GRIPPER, "heldZ") if z is not None]
    assert heights[0] < 0.05 and max(heights) > 0.2           # picked from the table, lifted well clear
    closed_at = next(t for t, s in status if s == "Closed")
    released_at = next(t for t, s in status if t > closed_at and s == "Open")
    phase_start = {name: t for t, name in trace.series("pick_place.eventName")}
    assert phase_start["gripper_close"] <= closed_at < phase_start["gripper_open"] <= released_at
    forces = [f for _, f in trace.gripper_series(GRIPPER, "force") if f is not None]
    assert forces and all(f >= 0.0 for f in forces)
