"""The scene and lanes part of a live frame: what the page's 3D scene and lanes need of the ticks a frame covers.

A frame covers every tick since the previous one (one frame at most every 1/30 s, however many ticks
ran). The scene needs only where each moving body is now, so each body's last pose sample of the
frame is sent, rounded as the report rounds it; the lanes are timelines, so every change of a
controller phase and of a gripper field within the frame is kept with its tick (they change a
few times a run, so this stays small), and a gripper's rays and force limits when a close begins.
"""
from __future__ import annotations

from graphflow.report.build import POSE_DECIMALS


def _rounded(pose: list[float]) -> list[float]:
    return [round(value, POSE_DECIMALS) + 0.0 for value in pose]   # + 0.0: no -0.0


def scene_part(header: dict, records: list[dict]) -> dict:
    """``scene`` (last pose per moving body, closes' rays) and ``lanes`` (phase and gripper changes) of *records*.

    *header* is the trace's header record: it names the outputs that carry a controller's phase.
    """
    phases = set(header.get("phases", ()))
    poses: dict[str, list] = {}
    rays: list[dict] = []
    phase_changes: dict[str, list] = {}
    gripper_changes: dict[str, dict[str, list]] = {}
    for record in records:
        tick = record["tick"]
        for path, pose in record.get("poses", {}).items():
            poses[path] = [tick, pose]
        for key, value in record.get("outputs", {}).items():
            if key in phases:
                phase_changes.setdefault(key, []).append([tick, value])
        for path, fields in record.get("grippers", {}).items():
            series = gripper_changes.setdefault(path, {})
            for name, value in fields.items():
                series.setdefault(name, []).append([tick, value])
        for path, close in record.get("rays", {}).items():
            rays.append({"tick": tick, "gripper": path, "rays": close["rays"], "limits": close["limits"]})
    return {"scene": {"poses": {path: [tick, _rounded(pose)] for path, (tick, pose) in poses.items()}, "rays": rays},
            "lanes": {"phases": phase_changes, "grippers": gripper_changes}}
