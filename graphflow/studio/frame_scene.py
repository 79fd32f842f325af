"""The scene and lanes part of a live frame: what the page's 3D scene and lanes need of the ticks a frame covers.

A frame covers every tick since the previous one (one frame at most every 1/30 s, however many ticks
ran). The scene needs only where each moving body is now, so the poses are read when the frame is
made, rounded as the report rounds them, and only those that moved are sent. The lanes are
timelines, and a gripper that closes in one tick or a controller phase shorter than a frame must
still show, so a listener notes on each tick the changes of the controller phases and of each
gripper's status, held objects and reason (a few comparisons a tick); the holding force, a plot,
is read with the frame. On the tick a gripper starts to close, its rays are cast as the trace's are (the
scene draws them and their nearest hits). Nothing here depends on the trace being recorded.
"""
from __future__ import annotations

from typing import Any

from graphflow.observe.trace import (
    GripperSample,
    phase_outputs,
    surface_gripper_manager,
    to_json_value,
    used_grippers,
)
from graphflow.observe.trace_scene import close_rays, force_limits
from graphflow.report.build import POSE_DECIMALS

TICK_FIELDS = ("status", "gripped", "reason")   # gripper fields noted on every tick; the others once a frame


def _rounded(pose) -> list[float]:
    (x, y, z), (qx, qy, qz, qw) = pose
    return [round(float(value), POSE_DECIMALS) + 0.0 for value in (x, y, z, qx, qy, qz, qw)]   # + 0.0: no -0.0


class FrameScene:
    """The ``scene`` and ``lanes`` of each frame of one live simulation; ``frame()`` when a frame is due."""

    def __init__(self, simulation):
        self.simulation = simulation
        world, instance = simulation.world, simulation.instance
        self._phases = []   # (the node's outputs dict, port name, "node.port") of each controller phase
        for key in phase_outputs(instance.compiled):
            node, port = key.rsplit(".", 1)
            self._phases.append((instance.database(node).outputs.__dict__, port, key))
        self._last: dict[str, Any] = {key: to_json_value(values[port]) for values, port, key in self._phases}
        description = getattr(world, "description", None)
        self._unused = {g.path for g in getattr(description, "surface_grippers", ())} - set(used_grippers(simulation))
        bodies = dict(getattr(description, "bodies", {}) or {})
        self._moving = [path for path, body in bodies.items() if body.kind != "static"]
        self._poses = {path: _rounded(pose) for path, pose in zip(self._moving, world.body_poses(self._moving))}
        self._changes: dict[str, list] = {}
        self._gripper_changes: dict[str, dict[str, list]] = {}
        self._gripper_last: dict[str, dict[str, Any]] = {}
        self._frame_fields: dict[str, dict[str, Any]] = {}
        self._limited: set[str] = set()
        self._closes: list[dict] = []   # the rays of each close since the last frame, as the report's run data lists them
        self._manager = None   # the world's gripper manager, once a node has made it
        simulation.add_listener(self)

    def on_tick(self, simulation, tick: int) -> None:
        """Note the phase and gripper changes of the tick that just ran."""
        count = simulation.instance.tick_count
        for values, port, key in self._phases:
            value = to_json_value(values[port])
            if value != self._last[key]:
                self._last[key] = value
                self._changes.setdefault(key, []).append([count, value])
        manager = self._manager
        if manager is None:
            manager = self._manager = surface_gripper_manager(simulation.world)
            if manager is None:
                return
        for path in manager.components:
            if path in self._unused:
                continue
            now = {"status": manager.get_gripper_status(path).token, "gripped": list(manager.get_gripped_objects(path)),
                   "reason": manager.component(path).reason}
            last = self._gripper_last.setdefault(path, {})
            if last.get("status", "Open") == "Open" and now["status"] != "Open":
                self._closes.append({"tick": count, "gripper": path,
                                     "rays": close_rays(simulation.world, manager.component(path))})
            for name, value in now.items():
                if name not in last or last[name] != value:
                    last[name] = value
                    self._gripper_changes.setdefault(path, {}).setdefault(name, []).append([count, value])

    def frame(self, samples: dict[str, GripperSample]) -> dict:
        """``scene`` (poses of bodies that moved, grippers' force limits when first seen, closes' rays) and ``lanes``
        since the last; *samples*: the grippers now (``sample_grippers``, read once a frame for this and the panel)."""
        world, tick = self.simulation.world, self.simulation.instance.tick_count
        poses = {}
        for path, read in zip(self._moving, world.body_poses(self._moving)):
            pose = _rounded(read)
            if pose != self._poses[path]:
                poses[path] = [tick, pose]
                self._poses[path] = pose
        grippers, self._gripper_changes = self._gripper_changes, {}
        limits = {}
        for path, sample in samples.items():
            if path in self._unused:
                continue
            for name, value in sample.fields().items():
                if name not in TICK_FIELDS and self._frame_fields.setdefault(path, {}).get(name, "unset") != value:
                    self._frame_fields[path][name] = value
                    grippers.setdefault(path, {})[name] = [[tick, value]]
            if path not in self._limited:
                self._limited.add(path)
                limits[path] = force_limits(surface_gripper_manager(world).component(path))
        phases, self._changes = self._changes, {}
        closes = sorted(self._closes, key=lambda close: (close["tick"], close["gripper"]))   # the report's order
        self._closes = []
        return {"scene": {"poses": poses, "limits": limits, "rays": closes},
                "lanes": {"phases": phases, "grippers": grippers}}

def merge_parts(older: dict, newer: dict) -> dict:
    """The scene and lanes parts of two consecutive frames as one: the newest poses and limits, every lane change and close.

    For a live loop that merges frames waiting for a slow socket: ``{**older, **newer}`` would drop
    the older frame's lane changes and the poses of bodies that moved only in it.
    """
    lanes: dict[str, dict[str, Any]] = {"phases": {key: list(changes) for key, changes in older["lanes"]["phases"].items()},
             "grippers": {path: {name: list(changes) for name, changes in fields.items()}
                          for path, fields in older["lanes"]["grippers"].items()}}
    for key, changes in newer["lanes"]["phases"].items():
        lanes["phases"].setdefault(key, []).extend(changes)
    for path, fields in newer["lanes"]["grippers"].items():
        for name, changes in fields.items():
            lanes["grippers"].setdefault(path, {}).setdefault(name, []).extend(changes)
    scene = {"poses": {**older["scene"]["poses"], **newer["scene"]["poses"]},
             "limits": {**older["scene"]["limits"], **newer["scene"]["limits"]},
             "rays": older["scene"]["rays"] + newer["scene"]["rays"]}
    return {"scene": scene, "lanes": lanes}
