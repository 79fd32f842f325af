"""Run listeners for a person at a terminal: the graph's log lines, a progress line, real-time pacing."""
from __future__ import annotations

import sys
import time

from graphflow.executor import LogEvent

PROGRESS_AFTER_SECONDS = 2.0


class PrintedLog:
    """The graph's log lines: info on stdout, warnings and errors on stderr."""

    @staticmethod
    def on_log(event: LogEvent) -> None:
        if event.level in ("warning", "warn", "error"):
            print(f"{event.level.upper()}: {event.node}: {event.message}", file=sys.stderr)
        else:
            print(event.message, flush=True)


class Progress:
    """A status line on a terminal for runs longer than a few seconds; silent otherwise."""

    def __init__(self, simulation, enabled: bool, limit: int | None = None):
        self.simulation = simulation
        self.enabled = enabled
        self.limit = limit
        self.started = time.perf_counter()
        self.last_shown = 0.0
        self.shown = False
        # the first node with an eventName output (a controller) names the current phase
        self.phase_node = next((node.name for node in simulation.compiled.nodes
                                if node.spec.attribute("outputs:eventName") is not None), None)

    def on_tick(self, _simulation, count: int) -> None:
        if not self.enabled or count % 32:
            return
        now = time.perf_counter()
        elapsed = now - self.started
        if elapsed < PROGRESS_AFTER_SECONDS or now - self.last_shown < 0.25:
            return
        self.last_shown = now
        sys.stderr.write("\r" + self.status(count, self.limit, elapsed))
        sys.stderr.flush()
        self.shown = True

    def status(self, count: int, limit: int | None, elapsed: float) -> str:
        """The status line: simulated time, tick, ticks per wall second and the controller's phase if any."""
        total = f"/{limit}" if limit else ""
        line = f"  t = {self.simulation.world.time:8.3f} s   tick {count}{total}   {count / elapsed:7.0f} ticks/s "
        if self.phase_node is not None:
            line += f"  phase {self.simulation.instance.output(self.phase_node, 'eventName') or '-':<20}"
        return line

    def on_end(self, _simulation, _result) -> None:
        """End the status line (also when the run failed or was interrupted)."""
        if self.shown:
            sys.stderr.write("\n")


class RealTimePacer:
    """Holds a --gui run to the pace of simulated time (times --speed), so people can watch it.

    Only the display is paced: the simulation never reads the wall clock, so a paced run
    computes exactly what a headless run does.
    """

    def __init__(self, speed: float):
        self.speed = speed
        self.started = time.perf_counter()

    def on_tick(self, simulation, _tick: int) -> None:
        ahead = simulation.world.time / self.speed - (time.perf_counter() - self.started)
        if ahead > 0:
            time.sleep(ahead)
