"""A graph running live for the studio: its own thread, driven by play/pause/step/reset/speed, streamed in frames.

The run is ``graphflow run``'s checked run (preflight, world, checks, the report's in-memory trace)
with the browser as keyboard and gamepad. Its thread owns the simulation (PyBullet is not shared
between threads); commands arrive through a queue. What changed is sent as one frame at most every
``FRAME_SECONDS`` of wall time, never once a tick, however fast the run goes: the tick range, the
outputs whose value changed (last value), the nodes that computed, gripper fields, body poses, log lines.
"""
from __future__ import annotations

import logging
import queue
import threading
import time
from dataclasses import replace
from pathlib import Path
from typing import Callable

from graphflow.document import load_document
from graphflow.errors import BadInput, GraphflowError
from graphflow.studio.browser_input import BrowserKeys, BrowserPad
from graphflow.studio.frame_scene import FrameScene

FRAME_SECONDS = 1 / 30
logger = logging.getLogger(__name__)
MAX_LOG_LINES = 200


class LiveRun:
    """One graph file running live; ``command()`` from any thread, frames to *publish* from the run's thread."""

    def __init__(self, path: Path, publish: Callable[[dict], None]):
        self.path, self.publish = path, publish
        self.keys, self.pad = BrowserKeys(), BrowserPad()
        self._commands: queue.Queue = queue.Queue()
        self._thread = threading.Thread(target=self._main, name=f"graphflow-live-{path.name}", daemon=True)
        self.playing, self.speed = False, 1.0   # speed None: as fast as it goes
        self._thread.start()

    def command(self, name: str, **fields) -> None:
        """Queue a command: play, pause, step, reset, speed (value: a factor or None), saveReport, saveTrace, close."""
        self._commands.put((name, fields))

    def close(self) -> None:
        self.command("close")
        self._thread.join(timeout=10)

    # --- the run's thread -------------------------------------------------------------------------------------
    def _main(self) -> None:
        try:
            self._load()
            self._loop()
        except GraphflowError as error:
            self.publish({"type": "error", "message": str(error), "fatal": True})
        except Exception as error:   # a bug: the page is told, the server goes on
            logger.exception("live run of %s failed", self.path)
            self.publish({"type": "error", "message": f"internal error: {error}", "fatal": True})
        finally:
            checked = getattr(self, "checked", None)
            if checked is not None:
                checked.close()

    def _load(self) -> None:
        from graphflow.report.build import run_data
        from graphflow.report.recording import ReportRecording
        from graphflow.verdicts.checked_run import CheckedRun, ScriptedInputs

        document = load_document(self.path)
        scripted = ScriptedInputs.of_document(document)
        self.checked = CheckedRun(document, source=str(self.path),
                                  inputs=replace(scripted, keys=self.keys, pad=self.pad))
        self.checked.preflight()
        self.simulation = self.checked.start()
        self.recording = ReportRecording(self.simulation, str(self.path))
        self.scene = FrameScene(self.simulation)
        self.limit = self.checked.tick_limit()
        self.ended, self.failure, self._sent = None, None, 0
        self.publish({"type": "start", "run": run_data(self.recording.trace(), document), "limit": self.limit})

    def _loop(self) -> None:
        next_frame = time.monotonic()
        while True:
            timeout = 0.0 if self._running() else None
            if self._running() and self.speed is not None:
                timeout = max(0.0, self._due - time.monotonic())
            try:
                name, fields = self._commands.get(timeout=timeout) if timeout != 0.0 else self._commands.get_nowait()
            except queue.Empty:
                name, fields = None, {}
            if name == "close":
                return
            if name is not None:
                self._handle(name, fields)
                self._frame()
                next_frame = time.monotonic() + FRAME_SECONDS
                continue
            if self._running() and (self.speed is None or time.monotonic() >= self._due):
                self._tick()
                if self.speed is not None:
                    self._due += self.simulation.world.time_step / self.speed
            if time.monotonic() >= next_frame or not self._running():
                self._frame()
                next_frame = time.monotonic() + FRAME_SECONDS

    def _running(self) -> bool:
        return self.playing and self.ended is None

    def _handle(self, name: str, fields: dict) -> None:
        if name == "play":
            self.playing, self._due = True, time.monotonic()
        elif name == "pause":
            self.playing = False
        elif name == "step":
            self.playing = False
            if self.ended is None:
                self._tick()
        elif name == "speed":
            value = fields.get("value")
            self.speed = None if value is None else float(value)
            self._due = time.monotonic()
        elif name == "reset":
            self._reset()
        elif name in ("saveReport", "saveTrace"):
            self._save(name, fields["path"])

    def _tick(self) -> None:
        from graphflow.executor import GraphRuntimeError
        from graphflow.runtime import RunResult

        simulation = self.simulation
        try:
            simulation.step()
        except GraphRuntimeError as error:
            self._end(None, failure=f"{self.path.name}: run-time failure: {error}")
            return
        count = simulation.tick_count
        stopped = any(instance.stop_requested for instance in simulation.instances)
        if stopped or (self.limit is not None and count >= self.limit):
            self._end(RunResult(count, simulation.world.time, stopped))

    def _end(self, result, failure: str | None = None) -> None:
        for listener in list(self.simulation.listeners):
            on_end = getattr(listener, "on_end", None)
            if on_end is not None:
                on_end(self.simulation, result)
        failures = [failure] if failure else [str(f) for f in self.checked.evaluator.finish(self.simulation, result)]
        self.failure = failure
        self.ended = {"passed": not failures, "failures": failures, "checks": len(self.checked.evaluator)}
        self.playing = False

    def _reset(self) -> None:
        self.checked.close()
        self.keys.rewind()
        self.pad.rewind()
        self._load()

    def _save(self, name: str, path: Path) -> None:
        from graphflow.observe.trace import dumps_record

        if name == "saveReport":
            evaluator = self.checked.evaluator if self.ended is not None else None
            self.recording.write(path, self.checked.document, evaluator=evaluator, runtime_failure=self.failure,
                                 seed=self.checked.seed, force=True)
        else:
            from graphflow.files import write_text

            write_text(path, "".join(dumps_record(record) + "\n" for record in self.recording.records), force=True)
        self.publish({"type": "saved", "what": name, "path": path.name})

    def _frame(self) -> None:
        """Everything recorded since the last frame, merged into one message."""
        records = self.recording.records[1 + self._sent:]
        self._sent += len(records)
        frame: dict = {"type": "frame", "tick": self.simulation.tick_count, "time": self.simulation.world.time,
                       "playing": self._running(), "speed": self.speed, "ended": self.ended,
                       "outputs": {}, "computed": [], "grippers": {}, "log": [],
                       **self.scene.frame()}
        computed: set[str] = set()
        for record in records:
            frame["outputs"].update(record.get("outputs", {}))
            computed.update(record.get("computed", ()))
            for path, fields in record.get("grippers", {}).items():
                frame["grippers"].setdefault(path, {}).update(fields)
            frame["log"].extend([record["tick"], line["node"], line["level"], line["message"]]
                                for line in record.get("log", ()))
        frame["computed"] = sorted(computed)
        frame["log"] = frame["log"][-MAX_LOG_LINES:]
        self.publish(frame)


def report_path(folder, relative: str) -> Path:
    """Where a save-as asked by the page goes: under the served folder, never over the graph itself."""
    path = folder.resolve(relative)
    if path.suffix not in (".html", ".jsonl"):
        raise BadInput(f"{relative}: a report is saved as .html, a trace as .jsonl")
    return path
