"""graphflow plot: the timeline carries the trace's series; missing ones are left out with a note."""
import json
import math
import subprocess
import sys
from pathlib import Path

import pytest
from conftest import ROOT

from graphflow.observe.timeline import timeline, timeline_figure
from graphflow.observe.trace import read_trace

matplotlib = pytest.importorskip("matplotlib")

GRIPPER = "/World/ur10/ee_link/SurfaceGripper"


def graphflow(*args):
    return subprocess.run([sys.executable, "-m", "graphflow", *args], capture_output=True, text=True)


def pick_trace(tmp_path) -> Path:
    """A small hand-written trace: a controller in three phases, a grip from tick 2 to tick 4."""
    header = {"format": "graphflow-trace", "version": 1, "graph": "pick.json", "stage": "asset:x.usda",
              "timeStep": 0.5, "nodes": {"tick": "omni.graph.action.OnTick", "ctrl": "graphflow.PickPlaceController"},
              "outputs": {"ctrl.eventName": ""}, "phases": ["ctrl.eventName"], "grippers": [], "versions": {}}
    ticks = [
        {"tick": 1, "t": 0.5, "pulses": ["tick.tick", "ctrl.execOut"], "outputs": {"ctrl.eventName": "approach"},
         "grippers": {GRIPPER: {"status": "Open", "gripped": [], "force": None, "heldZ": None}}},
        {"tick": 2, "t": 1.0, "pulses": ["tick.tick"], "outputs": {"ctrl.eventName": "lift"},
         "grippers": {GRIPPER: {"status": "Closed", "gripped": ["/World/Cube"], "force": 4.5, "heldZ": 0.1}}},
        {"tick": 3, "t": 1.5, "pulses": ["tick.tick"], "grippers": {GRIPPER: {"force": 5.0, "heldZ": 0.3}}},
        {"tick": 4, "t": 2.0, "pulses": ["tick.tick", "ctrl.execOut"], "outputs": {"ctrl.eventName": "release"},
         "grippers": {GRIPPER: {"status": "Open", "gripped": [], "force": None, "heldZ": None}}},
    ]
    path = tmp_path / "pick.jsonl"
    path.write_text("".join(json.dumps(record) + "\n" for record in [header, *ticks]))
    return path


def lines_by_panel(figure):
    return {axes.get_title(loc="left"): {line.get_label(): (list(line.get_xdata()), list(line.get_ydata()))
                                         for line in axes.get_lines() if not line.get_label().startswith("_")}
            for axes in figure.axes}


def test_pick_and_place_timeline_has_phase_status_height_force_and_pulses(tmp_path):
    data = timeline(read_trace(pick_trace(tmp_path)))
    panels = lines_by_panel(timeline_figure(data, "pick"))
    assert list(panels) == ["controller phase", "gripper status", "held object height",
                            "force on the gripper's attachments", "exec pulses"]
    assert data.notes == []
    phase_panel = next(p for p in data.panels if p.title == "controller phase")
    assert phase_panel.categories == ["(none)", "approach", "lift", "release"]
    assert panels["controller phase"]["ctrl.eventName"] == ([0.0, 0.5, 1.0, 2.0], [0, 1, 2, 3])
    assert panels["gripper status"][GRIPPER] == ([0.5, 1.0, 1.5, 2.0], [0, 2, 2, 0])
    heights = panels["held object height"][GRIPPER]
    assert heights[0] == [0.5, 1.0, 1.5, 2.0] and heights[1][1:3] == [0.1, 0.3]
    assert panels["force on the gripper's attachments"][GRIPPER][1][1:3] == [4.5, 5.0]
    assert panels["exec pulses"]["ctrl"][0] == [0.5, 2.0]


def test_a_core_graph_timeline_omits_gripper_and_phase_with_notes(tmp_path):
    trace_path = tmp_path / "counter.jsonl"
    assert graphflow("run", str(ROOT / "graphs" / "counter_branch_print.json"), "--trace", str(trace_path)).returncode == 0
    data = timeline(read_trace(trace_path))
    assert [p.title for p in data.panels] == ["exec pulses"]
    assert any("no controller phase" in note for note in data.notes)
    assert any("no surface gripper" in note for note in data.notes)
    panels = lines_by_panel(timeline_figure(data, "counter"))
    assert panels["exec pulses"]["print_count"][0] == [0.5, 1.0]
    assert panels["exec pulses"]["stop"][0] == [1.5]


def test_plot_command_embeds_the_series_in_the_png(tmp_path):
    Image = pytest.importorskip("PIL.Image")

    target = tmp_path / "timeline.png"
    result = graphflow("plot", str(pick_trace(tmp_path)), "-o", str(target))
    assert result.returncode == 0, result.stderr
    description = json.loads(Image.open(target).text["Description"])
    assert [p["title"] for p in description["panels"]][:2] == ["controller phase", "gripper status"]
    assert description["panels"][1]["series"] == {GRIPPER: 4}


def test_plot_of_a_non_trace_is_bad_input(tmp_path):
    result = graphflow("plot", str(ROOT / "graphs" / "counter_branch_print.json"), "-o", str(tmp_path / "x.png"))
    assert result.returncode == 2
    assert "not a graphflow trace" in result.stderr


def test_the_heavy_cube_timeline_shows_the_force_that_broke_the_legacy_grip(tmp_path):
    """Issue 26 item 4: the tutorial's 30 kg cube (294 N) on the legacy gripper's 200 N force limit: the force
    panel climbs past the limit to the break, as the run's reason says (it plotted ~1e-14 N before)."""
    trace = tmp_path / "heavy.jsonl"
    result = graphflow("run", str(ROOT / "graphs/scenarios/heavy_cube_breaks_grip.json"), "--trace", str(trace))
    assert "broken by force" in result.stdout + result.stderr
    data = timeline(read_trace(trace))
    forces = lines_by_panel(timeline_figure(data, "heavy"))["force on the gripper's attachments"]
    peak = max(value for value in forces["/World/ur10/ee_link/SurfaceGripper_01"][1] if math.isfinite(value))
    assert 200.0 < peak < 2 * 294.3
