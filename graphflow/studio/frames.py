"""The live run's frames, sampled from the simulation's latest state when one is due (never a tick at a time).

A frame says what changed since the previous frame: the outputs whose value differs (their value
now), the nodes that computed (compute counts moved), gripper fields that differ and the log lines
logged since; the scene's poses and the lanes' changes are ``graphflow.studio.frame_scene``'s part. Sampling costs the run nothing between frames:
no listener runs per tick or per compute, and no per-tick history is kept (the trace of a live run is
made again, identically, when the page saves it: ``graphflow.studio.replay``).
"""
from __future__ import annotations

import math
from typing import Any

from graphflow.observe.trace import GripperSample, to_json_value, used_grippers
from graphflow.studio.frame_scene import merge_parts

MAX_LOG_LINES = 200   # a frame carries at most the newest lines: the page shows a tail, the trace keeps them all


def _differs(previous: Any, value: Any) -> bool:
    """JSON values differ (a NaN equals a NaN: an output stuck at NaN is not sent again every frame)."""
    if isinstance(value, float) and isinstance(previous, float) and math.isnan(value) and math.isnan(previous):
        return False
    return previous != value


class FrameSampler:
    """Everything the page shows of one simulation, as differences from the last frame sampled."""

    def __init__(self, simulation):
        self.simulation = simulation
        instance = simulation.instance
        self._outputs = []   # (the node's outputs dict, port name, "node.port") of every data output
        for node in instance.compiled.nodes:
            executions = {attribute.name for attribute in node.spec.exec_outputs}
            values = instance.database(node.name).outputs.__dict__
            self._outputs.extend((values, name, f"{node.name}.{name}") for name in values if name not in executions)
        self._sent: dict[str, Any] = {key: to_json_value(values[name]) for values, name, key in self._outputs}
        self._counts = list(instance.compute_counts)
        description = getattr(simulation.world, "description", None)
        self._unused = {g.path for g in getattr(description, "surface_grippers", ())} - set(used_grippers(simulation))
        self._grippers: dict[str, dict] = {}
        self._logged_tick = instance.tick_count

    def frame(self, samples: dict[str, GripperSample]) -> dict:
        """The differences since the last call, as the ``frame`` message's fields; *samples*: the grippers now
        (``sample_grippers``, read once a frame for this and the lanes)."""
        instance = self.simulation.instance
        outputs = {}
        for values, name, key in self._outputs:
            value = to_json_value(values[name])
            if _differs(self._sent.get(key), value):
                outputs[key] = self._sent[key] = value
        counts = instance.compute_counts
        computed = sorted(node.name for node, before, now in zip(instance.compiled.nodes, self._counts, counts)
                          if now != before)
        self._counts = list(counts)
        grippers = {}
        for path, sample in samples.items():
            if path in self._unused:
                continue
            fields, previous = sample.fields(), self._grippers.get(path, {})
            changed = {key: value for key, value in fields.items() if key not in previous or _differs(previous[key], value)}
            if changed:
                grippers[path] = changed
            self._grippers[path] = fields
        return {"outputs": outputs, "computed": computed, "grippers": grippers, "log": self._log(instance)}

    def _log(self, instance) -> list:
        """Lines logged since the last frame, oldest first: [tick, node, level, message]."""
        lines: list[list[object]] = []
        for event in reversed(instance.events):
            if event.tick <= self._logged_tick or len(lines) == MAX_LOG_LINES:
                break
            lines.append([event.tick, event.node, event.level, event.message])
        self._logged_tick = instance.tick_count
        return lines[::-1]


def merge_frames(older: dict, newer: dict) -> dict:
    """One frame saying what two consecutive frames say: the newer state, the changes of both, every log line."""
    merged = {**older, **newer, "outputs": {**older["outputs"], **newer["outputs"]},
              "computed": sorted({*older["computed"], *newer["computed"]}),
              "log": (older["log"] + newer["log"])[-MAX_LOG_LINES:]}
    grippers = {path: dict(fields) for path, fields in older["grippers"].items()}
    for path, fields in newer["grippers"].items():
        grippers.setdefault(path, {}).update(fields)
    merged["grippers"] = grippers
    if "scene" in newer:   # the 3D scene's and lanes' part (frame_scene): the newest poses, every lane change of both
        merged.update(merge_parts(older, newer))
    return merged


class Outbox:
    """Messages waiting for a page's socket, in order; a frame that finds the last one still waiting merges into it.

    Back-pressure without blocking the run: a socket slower than the frames (a busy page, a slow
    link) gets fewer, fuller frames, and the messages waiting never grow beyond one frame.
    Used on the server's event loop only (the run's thread hands messages over with ``call_soon_threadsafe``).
    """

    def __init__(self):
        import asyncio
        from collections import deque

        self._waiting: deque = deque()
        self._ready = asyncio.Event()

    def put(self, message: dict) -> None:
        if message.get("type") == "frame" and self._waiting and self._waiting[-1].get("type") == "frame":
            self._waiting[-1] = merge_frames(self._waiting[-1], message)
        else:
            self._waiting.append(message)
        self._ready.set()

    def __len__(self) -> int:
        return len(self._waiting)

    async def take(self) -> dict:
        """The oldest waiting message, once there is one."""
        while not self._waiting:
            self._ready.clear()
            await self._ready.wait()
        return self._waiting.popleft()
