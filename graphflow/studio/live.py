"""A graph running live for the studio: its own thread, driven by play/pause/step/reset/speed, streamed in frames.

The run is ``graphflow run``'s checked run (preflight, world, checks) with the browser as keyboard
and gamepad. Its thread owns the simulation (PyBullet is not shared between threads); commands
arrive through a queue. At most every ``FRAME_SECONDS`` of wall time, never once a tick, a frame is
sampled from the latest state (``graphflow.studio.frames``): ticking costs what it costs headless
plus the checks, nothing is recorded per tick. Saving the trace or report replays the run with the
input it was fed (``graphflow.studio.replay``), which gives the identical trace, in a process of its
own while the live run goes on.
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
from graphflow.observe.trace import sample_grippers
from graphflow.studio.browser_input import BrowserKeys, BrowserMouse, BrowserPad
from graphflow.studio.frame_scene import FrameScene
from graphflow.studio.frames import FrameSampler
from graphflow.studio.replay import LiveInputs, save_in_background

FRAME_SECONDS = 1 / 30
logger = logging.getLogger(__name__)


class LiveRun:
    """One graph file running live; ``command()`` from any thread, frames to *publish* from the run's thread."""

    def __init__(self, path: Path, publish: Callable[[dict], object]):
        self.path, self.publish = path, publish
        self.keys, self.pad, self.mouse = BrowserKeys(), BrowserPad(), BrowserMouse()
        self._commands: queue.Queue = queue.Queue()
        self._thread = threading.Thread(target=self._main, name=f"graphflow-live-{path.name}", daemon=True)
        self.playing = False
        self.speed: float | None = 1.0     # None: as fast as it goes
        self._saving: set = set()   # replay processes writing a save (stopped if the run closes first)
        self._closed = False
        self._thread.start()

    def command(self, name: str, **fields) -> None:
        """Queue a command: play, pause, step, reset, speed (value: a factor or None), saveReport, saveTrace, close."""
        self._commands.put((name, fields))

    def close(self) -> None:
        self.command("close")
        self._thread.join(timeout=10)
        self._closed = True
        for process in self._saving:
            if process.is_alive():
                process.terminate()

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
        from graphflow.verdicts.checked_run import CheckedRun, ScriptedInputs

        document = load_document(self.path)
        scripted = ScriptedInputs.of_document(document)
        self.checked = CheckedRun(document, source=str(self.path),
                                  inputs=replace(scripted, keys=self.keys, pad=self.pad, mouse=self.mouse))
        self.checked.preflight()
        self.simulation = self.checked.start()
        self.sampler = FrameSampler(self.simulation)
        self.scene = FrameScene(self.simulation)
        self.limit = self.checked.tick_limit()
        self.ended: dict[str, object] | None = None
        self.publish({"type": "start", "run": run_data(_tick_zero(self.simulation, str(self.path)), document),
                      "limit": self.limit})

    def _loop(self) -> None:
        next_frame = time.monotonic()
        while True:
            timeout = None
            if self._running():
                timeout = 0.0 if self.speed is None else max(0.0, self._due - time.monotonic())
            name, fields = self._next_command(timeout)
            if name == "close":
                return
            if name is not None:
                self._handle(name, fields)
                self._frame()
                next_frame = time.monotonic() + FRAME_SECONDS
                continue
            if self._running():
                self._ticks_until(next_frame)
            if time.monotonic() >= next_frame or not self._running():
                self._frame()
                next_frame = time.monotonic() + FRAME_SECONDS

    def _next_command(self, timeout: float | None) -> tuple[str | None, dict]:
        """The next command, waiting up to *timeout* s (None: until one comes); (None, {}) when none came."""
        if timeout == 0.0 and self._commands.empty():
            return None, {}
        try:
            return self._commands.get(timeout=timeout or None) if timeout != 0.0 else self._commands.get_nowait()
        except queue.Empty:
            return None, {}

    def _ticks_until(self, next_frame: float) -> None:
        """Tick while no frame is due and no command waits: at max speed every tick due, in real time the next one."""
        commands, clock = self._commands, time.monotonic
        while self._running() and commands.empty():
            if self.speed is not None:
                if clock() < self._due:
                    return
                self._tick()
                self._due += self.simulation.world.time_step / self.speed
            else:
                self._tick()
            if clock() >= next_frame:
                return

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
        self.ended = {"passed": not failures, "failures": failures, "checks": len(self.checked.evaluator)}
        self.playing = False

    def _reset(self) -> None:
        self.checked.close()
        self.keys.rewind()
        self.pad.rewind()
        self.mouse.rewind()
        self._load()

    def _save(self, name: str, path: Path) -> None:
        """The trace or report of the ticks so far, made again from the input delivered in a process of its own:
        told when written (or why not); the live run does not wait."""
        inputs = LiveInputs(self.checked.document, str(self.path), self.keys.timeline(), self.pad.timeline(),
                            self.mouse.timeline())

        def done(failure: str | None) -> None:
            if self._closed:
                return
            if failure is None:
                self.publish({"type": "saved", "what": name, "path": path.name})
            else:
                self.publish({"type": "error", "message": f"{path.name} not saved: {failure}"})

        process = save_in_background(inputs, name, path, ticks=self.simulation.tick_count, ended=self.ended is not None,
                                     done=done)
        self._saving = {other for other in self._saving if other.is_alive()} | {process}

    def _frame(self) -> None:
        """What changed since the last frame, sampled from the simulation as it is now (the grippers read once)."""
        grippers = sample_grippers(self.simulation.world)
        self.publish({"type": "frame", "tick": self.simulation.tick_count, "time": self.simulation.world.time,
                      "playing": self._running(), "speed": self.speed, "ended": self.ended,
                      **self.sampler.frame(grippers), **self.scene.frame(grippers)})


class _Unlistened:
    """A simulation as a header-only recorder sees it: everything but ``add_listener`` (it records no tick)."""

    def __init__(self, simulation):
        self._simulation = simulation

    def __getattr__(self, name: str):
        return getattr(self._simulation, name)

    def add_listener(self, listener) -> None:
        """Not attached: the live run records nothing per tick."""


def _tick_zero(simulation, graph: str):
    """The trace of tick 0 (its header: graph, scene, starting values) that the page's ``start`` message draws."""
    from graphflow.observe.recorder import TraceRecorder
    from graphflow.observe.trace import Trace

    records: list[dict] = []
    TraceRecorder(_Unlistened(simulation), None, graph=graph, records=records)
    return Trace(records[0], [])


def report_path(folder, relative: str) -> Path:
    """Where a save-as asked by the page goes: under the served folder, never over the graph itself."""
    path = folder.resolve(relative)
    if path.suffix not in (".html", ".jsonl"):
        raise BadInput(f"{relative}: a report is saved as .html, a trace as .jsonl")
    return path
