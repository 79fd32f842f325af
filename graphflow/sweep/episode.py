"""One episode of a sweep, run in a worker: the graph through the one checked run, plus the sweep's metrics.

Each worker parses the graph once and keeps one ``Simulation``: an episode with the same overrides as the
previous one only resets it (about 10 ms); node overrides that differ give a new document (compiled once
per distinct set) and, like stage edits that differ, a new world parsed from the worker's open stage with a
fresh session layer (about 60 ms on the UR10 stage). Every episode seeds ``random`` and numpy's global
generator with its seed, as ``graphflow run --seed`` does, so an episode's record is the same whichever
worker runs it and whatever ran there before.
"""
from __future__ import annotations

import json
import math
import shlex
import time
from dataclasses import dataclass
from typing import Any, Mapping, Sequence

from graphflow.seeding import seed_everything
from graphflow.sweep.definition import Episode, Sweep
from graphflow.variants.overrides import (
    Override,
    Variant,
    apply_node_overrides,
    apply_stage_overrides,
)
from graphflow.verdicts.checks import CheckEvaluator

# ------------------------------------------------------------------ running episodes (in workers)

@dataclass(frozen=True)
class EpisodeRun:
    """How an episode's run ended: the run result (None if it raised), the error line, the measured metrics,
    and the graph's failed checks (one line each, with the gripper's or controller's reason)."""

    result: Any
    error: str | None
    metrics: Mapping[str, float | None]
    failed_checks: tuple[str, ...] = ()


def episode_verdict(simulation, run_result: EpisodeRun) -> tuple[bool, list[str]]:
    """Did the episode pass, and why not: the one place a sweep decides success.

    It passes when the run ended without a ``GraphRuntimeError`` (a failing
    node or ``graphflow.Assert``), every check of the graph holds (as
    ``graphflow run`` judges them), and every metric the sweep measures is a
    finite number (a metric that could not be measured, e.g. ``timeToFinish``
    of a run that hit its limit, fails it).
    """
    failures = []
    if run_result.error is not None:
        failures.append(run_result.error)
    failures.extend(run_result.failed_checks)
    for name, value in run_result.metrics.items():
        if value is None or not math.isfinite(value):
            failures.append(f"metric {name}: {_unmeasured_reason(name, value, run_result)}")
    return not failures, failures


def _unmeasured_reason(name: str, value, run_result: EpisodeRun) -> str:
    if value is None and run_result.result is not None and not run_result.result.stopped_by_graph:
        return f"not measured (the graph did not finish within {run_result.result.time:.3f} s)"
    return "not measured" if value is None else f"not finite ({value})"


class _MetricProbe:
    """Measures the sweep's metrics of one episode: peak grip forces per tick, positions at the end."""

    def __init__(self, metrics: Sequence[Mapping[str, Any]]):
        self.metrics = list(metrics)
        self.force_metrics = [m for m in self.metrics if "gripForce" in m]
        self.peaks = {m["name"]: 0.0 for m in self.force_metrics}
        self.jitter_metrics = [m for m in self.metrics if "holdJitter" in m]
        self.jitter = {m["name"]: _Jitter() for m in self.jitter_metrics}
        self.per_tick = bool(self.force_metrics or self.jitter_metrics)

    def after_tick(self, world) -> None:
        from graphflow.observe.trace import surface_gripper_manager

        manager = surface_gripper_manager(world)
        if manager is None:
            return
        for metric in self.jitter_metrics:
            spec = metric["holdJitter"]
            held = any(spec["prim"] in manager.get_gripped_objects(path) for path in manager.components)
            distance = math.dist(world.prim_pose(spec["prim"])[0], world.prim_pose(spec["relativeTo"])[0]) if held else None
            self.jitter[metric["name"]].add(distance, world.time_step)
        for metric in self.force_metrics:
            wanted = metric["gripForce"].get("gripper")
            for path, component in manager.components.items():
                if wanted is not None and path != wanted:
                    continue
                for handle in component.handles.values():
                    # the whole force on the gripper, drives included: what its force limit is compared with
                    force = manager.world.attachments.force_on_gripper(handle, False)
                    magnitude = math.sqrt(sum(float(f) * float(f) for f in force))
                    if magnitude > self.peaks[metric["name"]]:
                        self.peaks[metric["name"]] = magnitude

    def finish(self, world, result) -> dict[str, float | None]:
        values: dict[str, float | None] = {}
        for metric in self.metrics:
            name = metric["name"]
            if "positionError" in metric:
                spec = metric["positionError"]
                position = world.prim_pose(spec["prim"])[0]
                axes = {"xyz": (0, 1, 2), "xy": (0, 1), "z": (2,)}[spec.get("axes", "xyz")]
                values[name] = math.sqrt(sum((position[i] - spec["target"][i]) ** 2 for i in axes))
            elif "gripForce" in metric:
                values[name] = self.peaks[name]
            elif "holdJitter" in metric:
                values[name] = self.jitter[name].value()
            elif "timeToFinish" in metric:
                values[name] = result.time if result is not None and result.stopped_by_graph else None
        return values


class _Jitter:
    """RMS of d(distance)/dt over consecutive held ticks; None if the prim was never held two ticks running."""

    def __init__(self):
        self.previous: float | None = None
        self.total, self.count = 0.0, 0

    def add(self, distance: float | None, dt: float) -> None:
        if distance is not None and self.previous is not None:
            rate = (distance - self.previous) / dt
            self.total += rate * rate
            self.count += 1
        self.previous = distance

    def value(self) -> float | None:
        return math.sqrt(self.total / self.count) if self.count else None


class EpisodeRunner:
    """Runs episodes of one sweep in one process, reusing its simulation between them (see module doc)."""

    def __init__(self, sweep: Sweep):
        from graphflow.document import parse_document

        self.sweep = sweep
        self.base_document = parse_document(json.loads(json.dumps(sweep.graph_data)), sweep.graph_source)
        self.randomization = sweep.randomization()
        self.limits = sweep.limits()
        self._documents: dict[str, Any] = {}
        self._stage = None
        self._simulation = None
        self._simulation_key: tuple[str, str] | None = None
        self.rebuilds = 0     # worlds built (not reset) so far: the cost the module doc talks about
        self._warnings = _WarningLog()

    def _document(self, node_edits) -> Any:
        key = repr(node_edits)
        document = self._documents.get(key)
        if document is None:
            if len(self._documents) > 32:
                self._documents.clear()
            document = self._documents[key] = apply_node_overrides(self.base_document, node_edits)
        return document

    def _world(self, document, stage_edits):
        from graphflow.runtime import create_world

        settings = document.settings
        if self._stage is None:
            self._stage = Variant(document, ()).open_stage()
        self._stage.GetSessionLayer().Clear()
        apply_stage_overrides(self._stage, stage_edits)
        return create_world(self._stage, time_step=settings.get("timeStep"),
                                    substeps=settings.get("substeps"))

    def _simulation_for(self, edits):
        from graphflow.runtime import Simulation, create_world_for
        from graphflow.verdicts.checked_run import ScriptedInputs

        node_edits = [(e.target, e.value) for e in edits if not e.on_stage]
        stage_edits = [e for e in edits if e.on_stage]
        key = (repr(node_edits), repr([(getattr(e, "target", None), getattr(e, "value", None),
                                        getattr(e, "prim", None), getattr(e, "offset", None),
                                        getattr(e, "yaw_degrees", None)) for e in stage_edits]))
        if self._simulation is not None and key == self._simulation_key:
            self._simulation.reset()
            return self._simulation
        # A new graph gets a new world too: graph nodes author on the stage's session layer (the legacy
        # gripper does), so a world that another graph ran on is not the world a fresh run would get.
        if self._simulation is not None:
            self._simulation.close()
        document = self._document([e for e in edits if not e.on_stage])
        world = self._world(document, stage_edits) if document.settings.get("stage") else create_world_for(document)
        self.rebuilds += 1
        self._episode = _EpisodeListener(document)
        self._simulation = Simulation(document, world=world, listeners=[self._warnings, self._episode])
        ScriptedInputs.of_document(document).attach(world)   # the scenario's keys, gamepad and topics, as run and test
        self._simulation_key = key
        return self._simulation

    def run(self, episode: Episode) -> dict:
        """One episode's record (see docs/sweeps.md); never raises for a failing episode.

        The episode is one ``CheckedRun`` on this worker's reused simulation: the same verdict rule as
        ``graphflow run`` and ``graphflow test``; the sweep adds its metrics to it.
        """
        from graphflow.runtime import RunResult
        from graphflow.verdicts.checked_run import CheckedRun, RunLimits

        started = time.perf_counter()
        self._warnings.clear()
        edits = self.sweep.edits(episode)
        seed_everything(episode.seed)   # before the world is built, as graphflow run --seed does
        simulation = self._simulation_for(edits)
        probe = self._episode.start(_MetricProbe(self.sweep.data.get("metrics", [])))
        checked = CheckedRun(simulation.document, source=self.sweep.graph_source, seed=episode.seed,
                             limits=RunLimits(self.limits["ticks"], self.limits["seconds"]), simulation=simulation,
                             evaluator=self._episode.evaluator)   # attached once, with the metrics probe
        checked.start()
        verdict = checked.run()
        if verdict.run_error is None:
            result, error, failed_checks = RunResult(verdict.ticks, verdict.time, verdict.stopped_by_graph), None, \
                tuple(verdict.failures)
        else:
            result, error, failed_checks = None, f"run-time error: {verdict.run_error}", ()
        metrics = probe.finish(simulation.world, result)
        passed, failures = episode_verdict(simulation, EpisodeRun(result, error, metrics, failed_checks))
        drawn = {_edit_name(e): _edit_value(e) for e in edits[len(self.sweep.fixed_overrides()) + len(episode.parameters):]}
        return episode_record(episode, passed=passed, failures=failures, metrics=metrics, randomized=drawn,
                              ticks=verdict.ticks, time=simulation.world.time, finished=verdict.stopped_by_graph,
                              warnings=self._warnings.lines, wall=time.perf_counter() - started,
                              replay=shlex.join(self.sweep.replay_command(episode)))

    def close(self) -> None:
        if self._simulation is not None:
            self._simulation.close()
            self._simulation = None


class _EpisodeListener:
    """Run listener of an episode: the graph's checks and the sweep's per-tick metrics, every tick."""

    def __init__(self, document):
        self.document = document
        self.evaluator = CheckEvaluator(document)
        self.probe: _MetricProbe | None = None

    def start(self, probe: "_MetricProbe") -> "_MetricProbe":
        """A new episode: fresh checks (they keep what they saw), this episode's metric probe."""
        self.evaluator = CheckEvaluator(self.document)
        self.probe = probe if probe.per_tick else None
        return probe

    def on_tick(self, simulation, tick: int) -> None:
        self.evaluator.on_tick(simulation, tick)
        if self.probe is not None:
            self.probe.after_tick(simulation.world)


class _WarningLog:
    """The graph's warning and error lines of one episode (first 10, each once): why an episode went as it did."""

    def __init__(self):
        self.lines: list[str] = []

    def clear(self) -> None:
        self.lines = []

    def on_log(self, event) -> None:
        if event.level in ("warning", "warn", "error"):
            line = f"{event.node}: {event.message}"
            if line not in self.lines and len(self.lines) < 10:
                self.lines.append(line)


def quiet_logging() -> None:
    """Workers keep Python's warnings off the terminal: the graph's own warnings go into the records."""
    import logging

    logging.getLogger().setLevel(logging.ERROR)
    logging.getLogger("graphflow").setLevel(logging.ERROR)


def _edit_name(edit) -> str:
    return edit.target if isinstance(edit, Override) else f"{edit.prim}.pose"


def _edit_value(edit):
    if isinstance(edit, Override):
        return edit.value
    return {"offset": list(edit.offset), "yawDegrees": edit.yaw_degrees}


def episode_record(episode: Episode, *, passed: bool, failures: list[str], metrics: Mapping[str, Any],
                   randomized: Mapping[str, Any] | None = None, ticks: int = 0, time: float = 0.0,
                   finished: bool = False, warnings: Sequence[str] = (), wall: float = 0.0,
                   replay: str = "") -> dict:
    """The JSON record of one episode (one line of episodes.jsonl)."""
    return {"episode": episode.index, "key": episode.key, "point": episode.point, "seed": episode.seed,
            "parameters": dict(episode.parameters), "randomized": dict(randomized or {}),
            "passed": passed, "failures": list(failures), "metrics": dict(metrics),
            "warnings": list(warnings), "ticks": ticks, "time": round(time, 9), "finished": finished,
            "wall": round(wall, 4), "replay": replay}


def failed_record(episode: Episode, reason: str, metric_names: Sequence[str]) -> dict:
    """The record of an episode whose worker died or raised: failed, with the reason."""
    return episode_record(episode, passed=False, failures=[reason], metrics={name: None for name in metric_names})
