"""Timeline plots of a run trace: what the controller, the gripper and the held object did over time.

``graphflow plot run.jsonl -o run.png`` stacks panels that share the simulated
time axis: controller phase, gripper status, the held object's height, the
force on the gripper's attachment constraints, and which nodes fired exec
pulses. Panels whose data the trace lacks (no gripper, no controller) are left
out and a note at the bottom of the figure says so. The series drawn are also
embedded in the PNG's ``Description`` text chunk (JSON) so a picture can be checked.
"""
from __future__ import annotations

import json
import math
import textwrap
from dataclasses import dataclass, field
from pathlib import Path

from graphflow.observe.trace import Trace

GRIPPER_STATES = ("Open", "Closing", "Closed")
PHASE_TITLE = "controller phase"
NO_PHASE = "(none)"             # a controller's phase name before its first phase
FIGURE_WIDTH = 10.0            # inches
PANEL_HEIGHT = 1.6             # inches per value panel
ACTIVITY_ROW_HEIGHT = 0.2      # inches per node in the exec-pulse panel
REASON_LINES = 2               # lines of a gripper's reason written on the status panel


@dataclass
class Panel:
    """One subplot: its title, y label, kind (``category``, ``value`` or ``pulses``) and named series."""

    title: str
    ylabel: str
    kind: str
    series: dict[str, tuple[list[float], list]] = field(default_factory=dict)
    categories: list[str] = field(default_factory=list)
    labels: list[tuple[float, str, str]] = field(default_factory=list)   # (time, series, text) written on the plot


@dataclass
class Timeline:
    """The panels a trace supports and notes about the ones it does not."""

    panels: list[Panel]
    notes: list[str]
    end_time: float

    def describe(self) -> dict:
        """Series names and point counts per panel, plus notes: embedded in the PNG metadata."""
        return {"panels": [{"title": p.title, "series": {name: len(xs) for name, (xs, _) in p.series.items()},
                            **({"categories": p.categories} if p.categories else {}),
                            **({"labels": [[t, text] for t, _, text in p.labels]} if p.labels else {})}
                           for p in self.panels],
                "notes": self.notes}


def timeline(trace: Trace) -> Timeline:
    """Collect the series of every panel the trace has data for."""
    end_time = trace.ticks[-1]["t"] if trace.ticks else 0.0
    panels, notes = [], []

    phase = Panel(PHASE_TITLE, "phase", "category")
    for key in trace.header.get("phases", []):
        times, values = [0.0], [trace.header.get("outputs", {}).get(key) or NO_PHASE]
        for t, value in trace.series(key):
            times.append(t)
            values.append(value or NO_PHASE)
        phase.series[key] = (times, values)
        phase.categories += [v for v in values if v not in phase.categories]
    if phase.series:
        panels.append(phase)
    else:
        notes.append("no controller phase: no node in this graph has an eventName output")

    grippers = trace.gripper_paths
    if grippers:
        status = Panel("gripper status", "status", "category", categories=list(GRIPPER_STATES))
        height = Panel("held object height", "z (m)", "value")
        force = Panel("force on the gripper's attachments", "force (N)", "value")
        for path in grippers:
            status.series[path] = _unzip(trace.gripper_series(path, "status"))
            # why a close failed or a grip ended, written where it happened
            reasons = trace.gripper_series(path, "reason")
            status.labels += [(t, path, reason) for i, (t, reason) in enumerate(reasons)
                              if reason and (i == 0 or reasons[i - 1][1] != reason)]
            height.series[path] = _unzip(trace.gripper_series(path, "heldZ"))
            force.series[path] = _unzip(trace.gripper_series(path, "force"))
        panels.append(status)
        for panel, what in ((height, "held object height"), (force, "constraint force")):
            if any(v is not None for _, values in panel.series.values() for v in values):
                panels.append(panel)
            else:
                notes.append(f"no {what}: the gripper never held an object")
    else:
        notes.append("no gripper status, held object height or constraint force: this run had no surface gripper")

    pulses = Panel("exec pulses", "node", "pulses")
    for record in trace.ticks:
        for pulse in record.get("pulses", []):
            node = pulse.split(".", 1)[0]
            pulses.series.setdefault(node, ([], []))[0].append(record["t"])
    node_order = list(trace.header.get("nodes", {}))
    pulses.series = {n: (xs, [n] * len(xs)) for n, (xs, _) in
                     sorted(pulses.series.items(), key=lambda item: node_order.index(item[0]) if item[0] in node_order else len(node_order))}
    if pulses.series:
        panels.append(pulses)
    if not trace.ticks:
        notes.append("the trace holds no ticks")
    return Timeline(panels, notes, end_time)


def _unzip(points: list[tuple[float, object]]) -> tuple[list[float], list]:
    return [t for t, _ in points], [v for _, v in points]


def timeline_figure(data: Timeline, title: str):
    """A matplotlib Figure of a timeline (Agg backend; nothing is shown on screen)."""
    import matplotlib

    matplotlib.use("Agg")
    from matplotlib.figure import Figure
    from matplotlib.layout_engine import ConstrainedLayoutEngine

    heights = [max(1.0, len(p.series) * ACTIVITY_ROW_HEIGHT) if p.kind == "pulses" else PANEL_HEIGHT for p in data.panels]
    note_height = 0.25 * len(data.notes) + 0.3
    layout_engine = ConstrainedLayoutEngine()     # kept: the notes below reserve their strip through it
    fig = Figure(figsize=(FIGURE_WIDTH, sum(heights) + note_height + 0.9), dpi=110, layout=layout_engine)
    fig.suptitle(f"{title}: timeline", fontsize=12)
    if data.panels:
        axes_list = fig.subplots(len(data.panels), 1, sharex=True, squeeze=False,
                                 gridspec_kw={"height_ratios": heights})[:, 0]
        phase_changes = [t for panel in data.panels if panel.kind == "category" and panel.title == PHASE_TITLE
                         for times, _ in panel.series.values() for t in times[1:]]
        for axes, panel in zip(axes_list, data.panels):
            for t in phase_changes:      # phase boundaries across every panel, to line events up
                axes.axvline(t, color="#9ca3af", linewidth=0.6, linestyle=":", zorder=0)
            _draw_panel(axes, panel, data.end_time)
        axes_list[-1].set_xlabel("simulated time (s)")
        axes_list[-1].set_xlim(0.0, max(data.end_time, 1e-9))
    if data.notes:
        fig.text(0.01, 0.005, "\n".join(f"note: {n}" for n in data.notes), fontsize=8, color="#555", va="bottom")
        layout_engine.set(rect=(0, note_height / fig.get_figheight(), 1, 1 - note_height / fig.get_figheight()))
    return fig


def _draw_panel(axes, panel: Panel, end_time: float) -> None:
    axes.set_title(panel.title, fontsize=9, loc="left")
    axes.set_ylabel(panel.ylabel, fontsize=8)
    axes.tick_params(labelsize=8)
    axes.grid(True, axis="x", color="#e5e7eb", linewidth=0.6)
    if panel.kind == "pulses":
        names = list(panel.series)
        for row, (name, (times, _)) in enumerate(panel.series.items()):
            axes.plot(times, [row] * len(times), linestyle="none", marker="|", markersize=7, color="#374151", label=name)
        axes.set_yticks(range(len(names)), names)
        axes.set_ylim(len(names) - 0.5, -0.5)
        return
    for name, (times, values) in panel.series.items():
        times, values = list(times), list(values)
        if times and times[-1] < end_time:           # hold the last value to the end of the run
            times.append(end_time)
            values.append(values[-1])
        if panel.kind == "category":
            levels = [panel.categories.index(v) if v in panel.categories else math.nan for v in values]
            axes.step(times, levels, where="post", linewidth=1.8, label=name)
        else:
            axes.plot(times, [math.nan if v is None else v for v in values], linewidth=1.4, label=name)
    for t, name, text in panel.labels:
        values = panel.series[name][1]
        times = panel.series[name][0]
        value = next((v for when, v in zip(reversed(times), reversed(values)) if when <= t), None)
        level = panel.categories.index(value) if value in panel.categories else 0
        lines = textwrap.wrap(text, 100)
        shown = "\n".join(lines[:REASON_LINES]) + (" ..." if len(lines) > REASON_LINES else "")
        axes.annotate(shown, (t, level), xytext=(3, 5), textcoords="offset points", fontsize=6.5, color="#b91c1c",
                      va="bottom")
    if panel.kind == "category":
        axes.set_yticks(range(len(panel.categories)), panel.categories)
        axes.set_ylim(-0.5, len(panel.categories) - 0.5)
    if len(panel.series) > 1 or panel.kind == "value":
        axes.legend(fontsize=7, loc="upper right", frameon=False)


def write_timeline(trace: Trace, path: str | Path) -> Timeline:
    """Save the timeline (format from the suffix; PNG carries the series description as metadata)."""
    data = timeline(trace)
    fig = timeline_figure(data, Path(str(trace.header.get("graph") or "run")).name)
    metadata = {"Description": json.dumps(data.describe())} if str(path).lower().endswith(".png") else None
    fig.savefig(path, metadata=metadata, facecolor="white")
    return data
