"""The report's data: a trace (docs/trace.md) regrouped per key for the page, plus layout, verdict and run header.

The page looks values up by tick, so every output, gripper field and body pose
becomes a list of changes ``[[tick, value], ...]`` (tick 0: before the first
tick). Outputs keep the trace's exact values (the page shows the very number
the run computed); poses are samples the page interpolates between, so a body
that rested gets a sample at the last tick it was still at rest; body poses are rounded to 10 µm and 1e-5 of a quaternion
component, which no one sees on screen and which keeps a long run's report small.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

from graphflow.observe.draw import HEADER_HEIGHT, ROW_HEIGHT, layout
from graphflow.observe.trace import Trace

POSE_DECIMALS = 5


@dataclass(frozen=True)
class RunInfo:
    """What a trace does not say about its run: seed, --set overrides, drawn randomization, verdict, timings."""

    seed: int | None = None
    overrides: tuple[str, ...] = ()
    randomization: dict = field(default_factory=dict)
    checks: tuple[dict, ...] | None = None     # graphflow.report.verdict entries; None: the run was not judged
    timings: dict | None = None                # node -> {"computes", "seconds"}: wall clock, when asked for


def graph_layout(document) -> dict:
    """Boxes and wires as ``graphflow draw`` places them (graphflow.draw.layout), for React Flow."""
    picture = layout(document)
    nodes = []
    for box in picture.boxes:
        rows = max(len(box.inputs), len(box.outputs))
        nodes.append({
            "name": box.name, "type": box.type_id, "role": box.role, "x": box.x, "y": box.y,
            "width": box.width, "height": box.height,
            "inputs": [{"name": p.name, "kind": p.kind, "y": p.y} for p in box.inputs],
            "outputs": [{"name": p.name, "kind": p.kind, "y": p.y} for p in box.outputs],
            "settings": list(box.settings), "settingsTop": HEADER_HEIGHT + rows * ROW_HEIGHT})
    edges = [{"src": edge.src, "dst": edge.dst, "kind": edge.kind} for edge in picture.edges]
    return {"nodes": nodes, "edges": edges}


def json_safe(value):
    """JSON.parse reads no NaN or Infinity: non-finite floats become their names as strings."""
    if isinstance(value, float) and not math.isfinite(value):
        return "NaN" if math.isnan(value) else ("Infinity" if value > 0 else "-Infinity")
    if isinstance(value, list):
        return [json_safe(item) for item in value]
    if isinstance(value, dict):
        return {key: json_safe(item) for key, item in value.items()}
    return value


def _rounded_pose(pose: list[float]) -> list[float]:
    return [round(value, POSE_DECIMALS) + 0.0 for value in pose]   # + 0.0: no -0.0 in the file


def run_data(trace: Trace, document, info: RunInfo = RunInfo()) -> dict:
    """The JSON object the page reads (see frontend/src/data.js)."""
    header = trace.header
    node_index = {name: index for index, name in enumerate(header.get("nodes", {}))}
    last_tick = trace.ticks[-1]["tick"] if trace.ticks else 0
    times = [0.0] * (last_tick + 1)
    computed: list[list[int]] = [[] for _ in range(last_tick + 1)]
    outputs = {key: [[0, value]] for key, value in header.get("outputs", {}).items()}
    grippers: dict[str, dict[str, list]] = {path: {} for path in header.get("grippers", [])}
    scene = header.get("scene") or {"upAxis": "Z", "poseEvery": None, "bodies": []}
    poses = {body["path"]: [[0, _rounded_pose(body["pose"])]] for body in scene["bodies"] if body["kind"] != "static"}
    pulses: list = []
    log: list = []
    rays: list = []
    limits: dict = {}
    pose_every = scene.get("poseEvery")
    for record in trace.ticks:
        tick = record["tick"]
        times[tick] = record["t"]
        computed[tick] = [node_index[name] for name in record.get("computed", ()) if name in node_index]
        for key, value in record.get("outputs", {}).items():
            outputs.setdefault(key, []).append([tick, value])
        for path, fields in record.get("grippers", {}).items():
            series = grippers.setdefault(path, {})
            for name, value in fields.items():
                series.setdefault(name, []).append([tick, value])
        for path, pose in record.get("poses", {}).items():
            rounded, track = _rounded_pose(pose), poses.setdefault(path, [])
            if track and track[-1][1] == rounded:
                continue
            if track and pose_every and tick - pose_every > track[-1][0]:
                track.append([tick - pose_every, track[-1][1]])   # it rested until the sample before: no glide
            track.append([tick, rounded])
        if "pulses" in record:
            pulses.append([tick, record["pulses"]])
        log.extend([tick, line["node"], line["level"], line["message"]] for line in record.get("log", ()))
        for path, close in record.get("rays", {}).items():
            rays.append({"tick": tick, "gripper": path, "rays": close["rays"]})
            limits[path] = [{"name": name, "value": value} for name, value in close["limits"].items()]
    return json_safe({
        "format": "graphflow-report", "version": 1,
        "header": {"graph": header.get("graph"), "description": header.get("description", ""),
                   "stage": header.get("stage"), "seed": info.seed, "overrides": list(info.overrides),
                   "randomization": info.randomization, "versions": header.get("versions", {}),
                   "timeStep": header.get("timeStep"), "poseEvery": scene.get("poseEvery"),
                   "traceVersion": header.get("version"), "judged": info.checks is not None,
                   "timings": info.timings is not None},
        "ticks": last_tick, "times": times, "graph": graph_layout(document), "outputs": outputs,
        "computed": computed, "pulses": pulses, "phases": header.get("phases", []), "grippers": grippers,
        "limits": limits, "log": log, "scene": scene, "poses": poses, "rays": rays,
        "checks": list(info.checks or ()), "timings": info.timings,
    })
