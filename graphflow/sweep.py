"""Sweeps: many episodes of one graph over a grid and/or random samples of overrides, with seeds per point.

``graphflow sweep SWEEP_FILE`` (format: docs/sweeps.md, schema:
graphflow/schema/sweep.schema.json) expands the sweep into episodes (point x
seed), runs them on a local process pool (one worker per core; ``-j``) or on
Ray (``--ray [ADDRESS]``), and appends one record per finished episode to
``episodes.jsonl`` and ``episodes.csv`` in ``--out DIR``. ``--resume`` runs
only the episodes the folder does not have yet; ``sweep.json`` there keeps the
sweep and graph the folder was started with, so a changed sweep is refused.

Each worker parses the graph once and keeps one ``Simulation``: an episode
with the same overrides as the previous one only resets it (about 10 ms);
node overrides that differ give a new document (compiled once per distinct
set) and, like stage edits that differ, a new world parsed from the worker's
open stage with a fresh session layer (about 60 ms on the UR10 stage). Every episode
seeds ``random`` and numpy's global generator with its seed, as ``graphflow
run --seed`` does, so an episode's record is the same whichever worker runs
it and whatever ran there before.
"""
from __future__ import annotations

import csv
import io
import json
import math
import os
import shlex
import sys
import time
from collections import deque
from dataclasses import dataclass
from itertools import product
from pathlib import Path
from typing import Any, Iterable, Mapping, Sequence

from .checks import CheckEvaluator
from .overrides import Override, OverrideError, PoseJitter, Scenario, apply_node_overrides, apply_stage_overrides
from .randomize import RandomizationError, draw, parse_randomization, schema_problems, stream
from .seeding import seed_everything

SWEEP_FORMAT = "graphflow-sweep"
EPISODES_JSONL, EPISODES_CSV = "episodes.jsonl", "episodes.csv"
SUMMARY_CSV, SUMMARY_JSON, MANIFEST = "summary.csv", "summary.json", "sweep.json"
WILSON_Z = 1.959963984540054   # the 97.5 % quantile of the standard normal: a two-sided 95 % interval


class SweepError(ValueError):
    """A sweep that cannot start (bad file, bad override, folder in the way); one line, exit code 2."""


# ------------------------------------------------------------------ the sweep definition

@dataclass(frozen=True)
class Episode:
    """One run: a parameter point and a seed. ``key`` names it in the results (and for --resume)."""

    index: int
    point: int
    seed: int
    parameters: Mapping[str, Any]

    @property
    def key(self) -> str:
        return f"p{self.point}-s{self.seed}"


@dataclass(frozen=True)
class Sweep:
    """A sweep file as data: plain JSON values only, so it travels to pool and Ray workers as is."""

    data: Mapping[str, Any]
    source: str
    graph_data: Mapping[str, Any]
    graph_source: str

    @property
    def parameter_names(self) -> list[str]:
        names = list(self.data.get("grid", {}))
        names += [n for n in self.data.get("samples", {}).get("parameters", {}) if n not in names]
        return names

    @property
    def metric_names(self) -> list[str]:
        return [metric["name"] for metric in self.data.get("metrics", [])]

    def points(self) -> list[dict[str, Any]]:
        """Every grid combination (last key fastest) combined with every random sample."""
        grid = self.data.get("grid", {})
        grid_points = [dict(zip(grid, values)) for values in product(*grid.values())] if grid else [{}]
        samples = self.data.get("samples")
        if not samples:
            return grid_points
        sampled = []
        for index in range(samples["count"]):
            sampled.append({name: _json_number(draw(distribution, stream("sample", samples.get("seed", 0), index, name)))
                            for name, distribution in samples["parameters"].items()})
        return [{**grid_point, **sample} for grid_point in grid_points for sample in sampled]

    def seeds(self) -> list[int]:
        seeds = self.data.get("seeds", 1)
        if isinstance(seeds, int):
            return list(range(seeds))
        start = seeds.get("start", 0)
        return list(range(start, start + seeds["count"]))

    def episodes(self) -> list[Episode]:
        seeds = self.seeds()
        return [Episode(point_index * len(seeds) + seed_index, point_index, seed, point)
                for point_index, point in enumerate(self.points()) for seed_index, seed in enumerate(seeds)]

    def randomization(self):
        return parse_randomization(self.data.get("randomize", []), self.source)

    def fixed_overrides(self) -> list[Override]:
        return [Override(target, value, origin=f"{self.source}: set {target}")
                for target, value in self.data.get("set", {}).items()]

    def edits(self, episode: Episode) -> list[Override | PoseJitter]:
        """What the episode changes, in the order it is applied: set, the point's parameters, randomize."""
        point = [Override(target, value, origin=f"{self.source}: {target}={json.dumps(value)}")
                 for target, value in episode.parameters.items()]
        return [*self.fixed_overrides(), *point, *self.randomization().draw(episode.seed)]

    def replay_command(self, episode: Episode) -> list[str]:
        """The ``graphflow run`` arguments that run this one episode alone (same overrides, scenario and seed)."""
        command = ["graphflow", "run", self.graph_source, "--seed", str(episode.seed)]
        for option in ("ticks", "seconds"):
            if self.data.get(option) is not None:
                command += [f"--{option}", str(self.data[option])]
        for target, value in {**self.data.get("set", {}), **episode.parameters}.items():
            command += ["--set", f"{target}={json.dumps(value)}"]
        if self.data.get("randomize"):
            command += ["--randomize", self.source]
        return command

    def limits(self) -> dict:
        seconds = self.data.get("seconds")
        if seconds is None and self.data.get("ticks") is None:
            seconds = self.graph_data.get("settings", {}).get("duration")
        return {"ticks": self.data.get("ticks"), "seconds": seconds}

    def identity(self) -> dict:
        """What the results of a folder depend on: the sweep and its graph as JSON values."""
        return {"sweep": self.data, "graph": self.graph_data}


def _json_number(value):
    return [float(v) for v in value] if isinstance(value, list) else value


def _read_json(path: str) -> Any:
    try:
        text = Path(path).read_text(encoding="utf-8")
    except FileNotFoundError:
        raise SweepError(f"{path}: file not found") from None
    except (OSError, UnicodeDecodeError) as error:
        raise SweepError(f"{path}: cannot read file: {error}") from None
    try:
        return json.loads(text)
    except json.JSONDecodeError as error:
        raise SweepError(f"{path}: malformed JSON at line {error.lineno} column {error.colno}: {error.msg}") from None


def load_sweep(path: str) -> Sweep:
    """Read, schema-check and resolve a sweep file; every override is checked before anything runs."""
    data = _read_json(path)
    problems = schema_problems(data, path)
    if problems:
        raise SweepError(problems[0])
    if data["formatVersion"][0] != 1:
        raise SweepError(f"{path}: formatVersion {data['formatVersion']} is not supported (this runtime reads 1.x)")
    graph_path = Path(path).resolve().parent / data["graph"]
    graph_data = _read_json(str(graph_path))
    sweep = Sweep(data, path, graph_data, str(graph_path))
    _check(sweep)
    return sweep


def _check(sweep: Sweep) -> None:
    """Fail before any episode runs: the graph, conflicting targets, and every point's overrides."""
    from .document import GraphError, parse_document

    try:
        document = parse_document(json.loads(json.dumps(sweep.graph_data)), sweep.graph_source)
    except GraphError as error:
        raise SweepError(str(error.problems[0])) from None
    try:
        randomization = sweep.randomization()
    except RandomizationError as error:
        raise SweepError(str(error)) from None
    swept = set(sweep.parameter_names) | set(sweep.data.get("set", {}))
    for target in randomization.targets:
        if target in swept:
            raise SweepError(f"{sweep.source}: {target} is both swept (set/grid/samples) and randomized; "
                             "the randomized value would hide the swept one")
    grid, samples = sweep.data.get("grid", {}), sweep.data.get("samples", {}).get("parameters", {})
    fixed = sweep.data.get("set", {})
    for target in [*grid, *samples]:
        if (target in grid and target in samples) or target in fixed:
            raise SweepError(f"{sweep.source}: {target} appears twice (in two of set, grid and samples)")
    for name in sweep.metric_names:
        if sweep.metric_names.count(name) > 1:
            raise SweepError(f"{sweep.source}: metrics: the name {name!r} is used twice")
    stage = None
    episodes = sweep.episodes()
    first_of_point = {episode.point: episode for episode in reversed(episodes)}
    try:
        for episode in sorted(first_of_point.values(), key=lambda e: e.index):
            edits = sweep.edits(episode)
            apply_node_overrides(document, [e for e in edits if not e.on_stage])
            stage_edits = [e for e in edits if e.on_stage]
            if stage_edits:
                if stage is None:
                    stage = Scenario(document, tuple(stage_edits)).open_stage()
                else:
                    stage.GetSessionLayer().Clear()
                    apply_stage_overrides(stage, stage_edits)
    except OverrideError as error:
        raise SweepError(str(error)) from None
    _check_metric_prims(sweep, document, stage)


def _check_metric_prims(sweep: Sweep, document, stage) -> None:
    """Every prim a metric names must be on the stage (else every episode would fail the same way)."""
    for index, metric in enumerate(sweep.data.get("metrics", [])):
        kind, spec = next((k, v) for k, v in metric.items() if k != "name")
        paths = [spec[key] for key in ("prim", "relativeTo", "gripper") if key in spec]
        if kind == "timeToFinish":
            continue
        if document.settings.get("stage") is None:
            raise SweepError(f"{sweep.source}: metrics/{index} ({metric['name']}): {kind} needs a graph with a stage")
        if stage is None:
            stage = Scenario(document, ()).open_stage()
        for path in paths:
            if not stage.GetPrimAtPath(path):
                raise SweepError(f"{sweep.source}: metrics/{index} ({metric['name']}): the stage has no prim {path}")


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
        from .trace import surface_gripper_manager

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
        from .document import parse_document

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
        from . import physics

        settings = document.settings
        if self._stage is None:
            self._stage = Scenario(document, ()).open_stage()
        self._stage.GetSessionLayer().Clear()
        apply_stage_overrides(self._stage, stage_edits)
        return physics.create_world(self._stage, time_step=settings.get("timeStep"),
                                    substeps=settings.get("substeps"))

    def _simulation_for(self, edits):
        from .runtime import Simulation, create_world_for

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
        self._simulation_key = key
        return self._simulation

    def run(self, episode: Episode) -> dict:
        """One episode's record (see docs/sweeps.md); never raises for a failing episode."""
        from .executor import GraphRuntimeError

        started = time.perf_counter()
        self._warnings.clear()
        edits = self.sweep.edits(episode)
        seed_everything(episode.seed)
        simulation = self._simulation_for(edits)
        probe = self._episode.start(_MetricProbe(self.sweep.data.get("metrics", [])))
        world = simulation.world
        result, error, failed_checks = None, None, ()
        try:
            result = simulation.run(ticks=self.limits["ticks"], seconds=self.limits["seconds"])
            failed_checks = tuple(str(f) for f in self._episode.evaluator.finish(simulation, result))
        except GraphRuntimeError as failure:
            error = f"run-time error: {failure}"
        metrics = probe.finish(world, result)
        passed, failures = episode_verdict(simulation, EpisodeRun(result, error, metrics, failed_checks))
        drawn = {_edit_name(e): _edit_value(e) for e in edits[len(self.sweep.fixed_overrides()) + len(episode.parameters):]}
        return episode_record(episode, passed=passed, failures=failures, metrics=metrics, randomized=drawn,
                              ticks=result.ticks if result else simulation.instance.tick_count,
                              time=world.time, finished=bool(result and result.stopped_by_graph),
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


def _quiet_logging() -> None:
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


# ------------------------------------------------------------------ executors: local pool and Ray

def _worker_main(connection, sweep: Sweep) -> None:
    """A pool worker: builds one runner, then runs the episodes it is sent until it gets None."""
    import signal

    signal.signal(signal.SIGINT, signal.SIG_IGN)   # Ctrl-C is the parent's to handle
    _quiet_logging()
    runner = None
    try:
        runner = EpisodeRunner(sweep)
        connection.send(("ready", None))
        while True:
            episode = connection.recv()
            if episode is None:
                break
            try:
                record = runner.run(episode)
            except Exception as error:   # the episode fails with its reason; the worker goes on
                record = failed_record(episode, f"worker error: {type(error).__name__}: {error}", sweep.metric_names)
            connection.send(("done", record))
    except (EOFError, BrokenPipeError, KeyboardInterrupt):
        pass
    except Exception as error:
        connection.send(("broken", f"{type(error).__name__}: {error}"))
    finally:
        if runner is not None:
            runner.close()


class LocalPool:
    """``jobs`` worker processes (spawned: no state shared with the parent), one episode in flight each.

    A worker that dies fails the episode it was running (its exit code or
    signal is the reason) and is replaced; the other episodes go on.
    """

    def __init__(self, sweep: Sweep, jobs: int):
        import multiprocessing

        self.sweep = sweep
        self.jobs = jobs
        self.context = multiprocessing.get_context("spawn")
        self.workers: list[dict] = []

    def _start_worker(self) -> dict:
        parent, child = self.context.Pipe()
        process = self.context.Process(target=_worker_main, args=(child, self.sweep), daemon=True)
        process.start()
        child.close()
        worker = {"process": process, "connection": parent, "episode": None, "ready": False}
        self.workers.append(worker)
        return worker

    def run(self, episodes: Sequence[Episode]) -> Iterable[dict]:
        from multiprocessing.connection import wait

        pending = list(reversed(episodes))
        for _ in range(min(self.jobs, len(episodes))):
            self._start_worker()
        try:
            while pending or any(w["episode"] is not None for w in self.workers):
                for worker in list(self.workers):
                    if worker["ready"] and worker["episode"] is None and pending:
                        try:
                            worker["connection"].send(pending[-1])
                        except (BrokenPipeError, OSError):
                            continue   # it died idle; wait() reports its end next
                        worker["episode"] = pending.pop()
                ready = wait([w["connection"] for w in self.workers])
                for worker in [w for w in self.workers if w["connection"] in ready]:
                    try:
                        kind, payload = worker["connection"].recv()
                    except (EOFError, OSError):
                        yield from self._replace(worker, pending)
                        continue
                    if kind == "ready":
                        worker["ready"] = True
                    elif kind == "done":
                        worker["episode"] = None
                        yield payload
                    else:
                        raise SweepError(f"{self.sweep.source}: a worker could not start: {payload}")
        except BaseException:   # Ctrl-C or the consumer stopped: finished episodes are already kept
            self.terminate()
            raise
        finally:
            self.close()

    def _replace(self, worker: dict, pending: list) -> Iterable[dict]:
        process = worker["process"]
        process.join(timeout=5)
        code = process.exitcode
        self.workers.remove(worker)
        worker["connection"].close()
        if worker["episode"] is None and not worker["ready"]:
            raise SweepError(f"{self.sweep.source}: a worker died while starting (exit code {code})")
        if worker["episode"] is not None:
            yield failed_record(worker["episode"], f"worker crashed ({_exit_reason(code)})", self.sweep.metric_names)
        if pending:
            self._start_worker()

    def terminate(self) -> None:
        """Stop every worker now, mid-episode if need be."""
        for worker in self.workers:
            worker["process"].terminate()
        for worker in self.workers:
            worker["process"].join()
            worker["connection"].close()
        self.workers = []

    def close(self) -> None:
        for worker in self.workers:
            try:
                worker["connection"].send(None)
            except (BrokenPipeError, OSError):
                pass
        for worker in self.workers:
            worker["process"].join(timeout=2)
            if worker["process"].is_alive():
                worker["process"].terminate()
                worker["process"].join()
            worker["connection"].close()
        self.workers = []


def _exit_reason(code: int | None) -> str:
    if code is None:
        return "no exit code"
    if code < 0:
        import signal

        try:
            return f"killed by {signal.Signals(-code).name}"
        except ValueError:
            return f"killed by signal {-code}"
    return f"exit code {code}"


class RayPool:
    """The same episodes on Ray: one actor per CPU (or ``jobs``), each an ``EpisodeRunner``.

    ``address`` None or ``"local"`` starts a local Ray; ``"auto"`` joins the
    running cluster, else starts a local one; anything else is a cluster
    address for ``ray.init``. Files the sweep names must exist at the same
    paths on every node. An actor that dies fails the episode it was running
    and is replaced; the episode it had queued runs again elsewhere.

    While more episodes wait than there are actors, each actor has a second
    episode queued behind the one it runs, so it starts the next one at once
    instead of idling through the driver's round trip (and whatever the
    consumer does with the record); the last ones are handed out one at a
    time, to whichever actor is free first.
    """

    def __init__(self, sweep: Sweep, jobs: int | None, address: str | None):
        try:
            import ray
        except ImportError:
            raise SweepError("--ray needs Ray: pip install 'graphflow[ray]'") from None
        self.ray = ray
        self.sweep = sweep
        self.jobs = jobs
        self.address = address
        self.actors: list[dict] = []   # {"actor": handle, "queue": deque of (reference, episode), running first}

    def _init(self) -> None:
        ray = self.ray
        options = {"include_dashboard": False, "log_to_driver": False, "logging_level": "ERROR"}
        if self.address in (None, "local"):
            ray.init(num_cpus=self.jobs, **options)
        elif self.address == "auto":
            try:
                ray.init(address="auto", **options)
            except ConnectionError:
                ray.init(num_cpus=self.jobs, **options)
        else:
            ray.init(address=self.address, **options)

    def _submit(self, pending: list) -> None:
        """Queue pending episodes on the actors: two each while plenty wait, else one each."""
        for worker in self.actors:
            while pending and len(worker["queue"]) < (2 if len(pending) > len(self.actors) else 1):
                episode = pending.pop()
                worker["queue"].append((worker["actor"].run.remote(episode), episode))

    def run(self, episodes: Sequence[Episode]) -> Iterable[dict]:
        ray = self.ray
        self._init()
        try:
            actor_class = ray.remote(num_cpus=1)(_RayEpisodeActor)
            count = self.jobs or max(1, int(ray.cluster_resources().get("CPU", 1)))
            pending = list(reversed(episodes))
            self.actors = [{"actor": actor_class.remote(self.sweep), "queue": deque()}
                           for _ in range(min(count, len(episodes)))]
            self._submit(pending)
            while any(worker["queue"] for worker in self.actors):
                # an actor runs its episodes in order, so only the first one of each can finish next
                running = {worker["queue"][0][0]: worker for worker in self.actors if worker["queue"]}
                done, _ = ray.wait(list(running), num_returns=1)
                worker = running[done[0]]
                _reference, episode = worker["queue"].popleft()
                try:
                    record = ray.get(done[0])
                except ray.exceptions.RayActorError as error:
                    record = failed_record(episode, f"worker crashed ({_first_line(error)})", self.sweep.metric_names)
                    pending.extend(queued for _reference, queued in reversed(worker["queue"]))
                    worker["actor"], worker["queue"] = actor_class.remote(self.sweep), deque()
                except ray.exceptions.RayTaskError as error:
                    record = failed_record(episode, f"worker error: {_first_line(error)}", self.sweep.metric_names)
                self._submit(pending)
                yield record
        finally:
            self.actors = []
            ray.shutdown()


def _first_line(error: BaseException) -> str:
    text = str(error).strip().splitlines()
    return text[0] if text else type(error).__name__


class _RayEpisodeActor:
    """A Ray actor around one ``EpisodeRunner`` (wrapped with ``ray.remote`` only when Ray is used)."""

    def __init__(self, sweep: Sweep):
        _quiet_logging()
        self.runner = EpisodeRunner(sweep)

    def run(self, episode: Episode) -> dict:
        try:
            return self.runner.run(episode)
        except Exception as error:
            return failed_record(episode, f"worker error: {type(error).__name__}: {error}", self.runner.sweep.metric_names)


# ------------------------------------------------------------------ results folder

class ResultsFolder:
    """``--out DIR``: the manifest, and the episode tables appended one whole line per finished episode."""

    def __init__(self, path: Path, sweep: Sweep):
        self.path = path
        self.sweep = sweep
        self.columns = (["episode", "key", "point", "seed"] + sweep.parameter_names
                        + ["passed", "failures"] + sweep.metric_names + ["warnings", "ticks", "time", "finished", "wall"])

    @property
    def jsonl(self) -> Path:
        return self.path / EPISODES_JSONL

    def existing(self) -> bool:
        return (self.path / MANIFEST).exists() or self.jsonl.exists()

    def start(self, *, resume: bool, force: bool) -> list[dict]:
        """Prepare the folder; return the records it already has (when resuming)."""
        if self.path.exists() and not self.path.is_dir():
            raise SweepError(f"{self.path}: exists and is not a folder")
        if self.existing() and not (resume or force):
            raise SweepError(f"{self.path}: already holds sweep results; --resume finishes them, "
                             "--force starts over, or choose another --out")
        self.path.mkdir(parents=True, exist_ok=True)
        manifest = self.path / MANIFEST
        if resume and self.existing():
            if not manifest.exists():
                raise SweepError(f"{manifest}: missing, so the results cannot be matched to the sweep; use --force")
            try:
                stored = json.loads(manifest.read_text(encoding="utf-8"))
            except (OSError, json.JSONDecodeError) as error:
                raise SweepError(f"{manifest}: unreadable ({error}); use --force") from None
            if stored.get("identity") != json.loads(json.dumps(self.sweep.identity())):
                raise SweepError(f"{self.path}: was started with a different sweep or graph; "
                                 "--force starts over, or choose another --out")
            records = self._read_records()
            _write_atomically(self.path / EPISODES_CSV, self._csv_text(records, header=True))
            return records
        for name in (EPISODES_JSONL, EPISODES_CSV, SUMMARY_CSV, SUMMARY_JSON):
            (self.path / name).unlink(missing_ok=True)
        _write_atomically(manifest, json.dumps({"format": "graphflow-sweep-results", "formatVersion": [1, 0],
                                                "source": self.sweep.source, "identity": self.sweep.identity()},
                                               indent=2) + "\n")   # key order kept: it orders grid points
        _write_atomically(self.path / EPISODES_CSV, self._csv_text([], header=True))
        return []

    def _read_records(self) -> list[dict]:
        """Whole lines only: a line cut short by a crash is dropped (and its episode runs again)."""
        if not self.jsonl.exists():
            return []
        data = self.jsonl.read_bytes()
        whole = data[: data.rfind(b"\n") + 1]
        if len(whole) != len(data):
            with open(self.jsonl, "r+b") as stream:
                stream.truncate(len(whole))
        records = []
        for line in whole.decode("utf-8").splitlines():
            try:
                records.append(json.loads(line))
            except json.JSONDecodeError:
                continue
        return records

    def _csv_text(self, records: Sequence[dict], *, header: bool) -> str:
        buffer = io.StringIO()
        writer = csv.writer(buffer, lineterminator="\n")
        if header:
            writer.writerow(self.columns)
        for record in records:
            writer.writerow([_cell(value) for value in self._row(record)])
        return buffer.getvalue()

    def _row(self, record: dict) -> list:
        parameters, metrics = record["parameters"], record["metrics"]
        return ([record["episode"], record["key"], record["point"], record["seed"]]
                + [parameters.get(name) for name in self.sweep.parameter_names]
                + [record["passed"], " | ".join(record["failures"])]
                + [metrics.get(name) for name in self.sweep.metric_names]
                + [" | ".join(record.get("warnings", [])), record["ticks"], record["time"], record["finished"], record["wall"]])

    def append(self, record: dict) -> None:
        """One whole line to each table, each written with a single write on an append-mode file."""
        for path, text in ((self.jsonl, json.dumps(record, sort_keys=True) + "\n"),
                           (self.path / EPISODES_CSV, self._csv_text([record], header=False))):
            with open(path, "a", encoding="utf-8", newline="") as stream:
                stream.write(text)
                stream.flush()


def _cell(value):
    if isinstance(value, (list, dict)):
        return json.dumps(value)
    if value is None:
        return ""
    return value


def _write_atomically(path: Path, text: str) -> None:
    temporary = path.with_name(f".{path.name}.tmp")
    temporary.write_text(text, encoding="utf-8")
    os.replace(temporary, path)


# ------------------------------------------------------------------ summary

def wilson_interval(successes: int, n: int, z: float = WILSON_Z) -> tuple[float, float]:
    """Wilson score interval of a binomial proportion (good at 0 %, 100 % and small n, unlike p ± z·se)."""
    if n == 0:
        return (0.0, 1.0)
    p = successes / n
    denominator = 1 + z * z / n
    centre = (p + z * z / (2 * n)) / denominator
    half = z * math.sqrt(p * (1 - p) / n + z * z / (4 * n * n)) / denominator
    return (max(0.0, centre - half), min(1.0, centre + half))


def summarize(sweep: Sweep, records: Sequence[dict]) -> list[dict]:
    """Per parameter point: n, passed, success rate with its 95 % Wilson interval, metric medians."""
    by_point: dict[int, list[dict]] = {}
    for record in records:
        by_point.setdefault(record["point"], []).append(record)
    rows = []
    points = sweep.points()
    for point in sorted(by_point):
        group = by_point[point]
        passed = sum(1 for r in group if r["passed"])
        low, high = wilson_interval(passed, len(group))
        medians = {}
        for name in sweep.metric_names:
            values = sorted(r["metrics"].get(name) for r in group if _finite(r["metrics"].get(name)))
            medians[name] = _median(values)
        rows.append({"point": point, "parameters": points[point] if point < len(points) else group[0]["parameters"],
                     "n": len(group), "passed": passed, "rate": passed / len(group),
                     "low": low, "high": high, "medians": medians})
    return rows


def _finite(value) -> bool:
    return isinstance(value, (int, float)) and not isinstance(value, bool) and math.isfinite(value)


def _median(values: Sequence[float]) -> float | None:
    if not values:
        return None
    middle = len(values) // 2
    return values[middle] if len(values) % 2 else (values[middle - 1] + values[middle]) / 2


def summary_lines(sweep: Sweep, rows: Sequence[dict]) -> list[str]:
    names = sweep.parameter_names
    header = [*names, "n", "passed", "rate", "95 % interval", *[f"median {m}" for m in sweep.metric_names]]
    table = [header]
    for row in rows:
        table.append([*[_shown(row["parameters"].get(name)) for name in names], str(row["n"]), str(row["passed"]),
                      f"{row['rate']:.0%}", f"{row['low']:.0%}-{row['high']:.0%}",
                      *[_shown(row["medians"][m]) for m in sweep.metric_names]])
    widths = [max(len(line[i]) for line in table) for i in range(len(header))]
    return ["  ".join(cell.rjust(width) for cell, width in zip(line, widths)) for line in table]


def _shown(value) -> str:
    if value is None:
        return "-"
    if isinstance(value, float):
        return f"{value:.4g}"
    return json.dumps(value) if isinstance(value, (list, dict)) else str(value)


def write_summary(folder: ResultsFolder, rows: Sequence[dict]) -> None:
    sweep = folder.sweep
    _write_atomically(folder.path / SUMMARY_JSON, json.dumps(rows, indent=2, sort_keys=True) + "\n")
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow(["point", *sweep.parameter_names, "n", "passed", "rate", "low95", "high95",
                     *[f"median_{m}" for m in sweep.metric_names]])
    for row in rows:
        writer.writerow([row["point"], *[_cell(row["parameters"].get(n)) for n in sweep.parameter_names], row["n"],
                         row["passed"], row["rate"], row["low"], row["high"],
                         *[_cell(row["medians"][m]) for m in sweep.metric_names]])
    _write_atomically(folder.path / SUMMARY_CSV, buffer.getvalue())


# ------------------------------------------------------------------ the command

class _Progress:
    """``done/total  passed  episodes/s  ETA`` on one terminal line; silent when stderr is not a terminal."""

    def __init__(self, total: int, already: int, enabled: bool):
        self.total, self.done, self.passed = total, already, 0
        self.started, self.new = time.perf_counter(), 0
        self.enabled = enabled

    def update(self, record: dict) -> None:
        self.done += 1
        self.new += 1
        self.passed += bool(record["passed"])
        if not self.enabled:
            return
        elapsed = time.perf_counter() - self.started
        rate = self.new / elapsed if elapsed > 0 else 0.0
        remaining = (self.total - self.done) / rate if rate > 0 else float("nan")
        width = 24
        filled = int(width * self.done / max(1, self.total))
        sys.stderr.write(f"\r  [{'#' * filled}{'.' * (width - filled)}] {self.done}/{self.total} episodes"
                         f"  {self.passed} passed  {rate:5.2f}/s  ETA {remaining:5.0f} s ")
        sys.stderr.flush()

    def finish(self) -> None:
        if self.enabled and self.new:
            sys.stderr.write("\n")


def default_out(sweep_path: str) -> Path:
    return Path("sweep-results") / Path(sweep_path).stem


def run_sweep(path: str, *, out: str | None = None, jobs: int | None = None, ray_address: str | None = None,
              use_ray: bool = False, resume: bool = False, force: bool = False, progress: bool | None = None,
              echo=print) -> int:
    """``graphflow sweep``: 0 when every episode ran (whatever their verdicts), 1 when interrupted."""
    sweep = load_sweep(path)
    folder = ResultsFolder(Path(out) if out else default_out(path), sweep)
    episodes = sweep.episodes()
    if use_ray:
        executor = RayPool(sweep, jobs, ray_address)
    else:
        executor = LocalPool(sweep, jobs or os.cpu_count() or 1)
    done = folder.start(resume=resume, force=force)
    finished_keys = {record["key"] for record in done}
    todo = [episode for episode in episodes if episode.key not in finished_keys]
    records = [record for record in done if record["key"] in {e.key for e in episodes}]
    where = f"Ray ({ray_address or 'local'})" if use_ray else f"{executor.jobs} local worker(s)"
    points, seeds = len(sweep.points()), len(sweep.seeds())
    echo(f"{path}: {len(episodes)} episodes ({points} point{'s' * (points != 1)} x {seeds} seed{'s' * (seeds != 1)})"
         + (f", {len(records)} already done, {len(todo)} to run" if resume else "") + f" on {where}; results in {folder.path}")
    bar = _Progress(len(episodes), len(records), sys.stderr.isatty() if progress is None else progress)
    interrupted = False
    running = executor.run(todo) if todo else (record for record in ())
    try:
        for record in running:
            folder.append(record)
            records.append(record)
            bar.update(record)
    except KeyboardInterrupt:
        interrupted = True
    finally:
        running.close()
        bar.finish()
    rows = summarize(sweep, records)
    write_summary(folder, rows)
    for line in summary_lines(sweep, rows):
        echo(line)
    passed = sum(1 for r in records if r["passed"])
    echo(f"{passed}/{len(records)} episodes passed; wrote {folder.path / EPISODES_CSV}, {folder.jsonl.name}, "
         f"{SUMMARY_CSV}")
    if interrupted:
        echo(f"interrupted: {len(records)} of {len(episodes)} episodes kept; "
             f"graphflow sweep {path} --out {folder.path} --resume runs the rest", file=sys.stderr)
        return 1
    return 0


def command_sweep(args) -> int:
    """The CLI handler (``graphflow sweep SWEEP`` and ``graphflow sweep plot DIR``); bad input: one line, exit 2."""
    try:
        if args.sweep == "plot":
            return args.plot_handler(args)
        if args.results is not None:
            raise SweepError(f"unexpected argument {args.results!r} (graphflow sweep SWEEP_FILE [options])")
        return run_sweep(args.sweep, out=args.out, jobs=args.jobs, use_ray=args.ray is not None,
                         ray_address=None if args.ray in (None, "") else args.ray, resume=args.resume,
                         force=args.force)
    except SweepError as error:   # reported as the CLI reports BadInput
        print(f"graphflow: error: {error}", file=sys.stderr)
        return 2


def add_sweep_parser(commands, plot_handler) -> None:
    """``graphflow sweep`` on the CLI's subcommands (kept here so cli.py only calls this).

    *plot_handler* (``graphflow.sweep_plot.plot_command``) handles ``graphflow sweep plot DIR``; it is
    passed in because the plotting module builds on this one.
    """
    sweep = commands.add_parser(
        "sweep", help="run many episodes: a grid / random samples of overrides x seeds (docs/sweeps.md); "
                      "'graphflow sweep plot DIR' plots the results")
    sweep.add_argument("sweep", metavar="SWEEP_FILE", help="sweep JSON file, or 'plot' to plot a results folder")
    sweep.add_argument("results", nargs="?", metavar="DIR", help="with 'plot': the results folder (--out of the sweep)")
    sweep.add_argument("--out", metavar="DIR", help="results folder (default sweep-results/SWEEP_NAME)")
    sweep.add_argument("-j", "--jobs", type=int, metavar="N", help="worker processes (default: one per core)")
    sweep.add_argument("--ray", nargs="?", const="", metavar="ADDRESS",
                       help="run the episodes on Ray: no ADDRESS or 'local' starts a local Ray, 'auto' joins the "
                            "running cluster (needs pip install 'graphflow[ray]')")
    sweep.add_argument("--resume", action="store_true", help="run only the episodes the results folder lacks")
    sweep.add_argument("--force", action="store_true", help="discard the results folder's episodes and start over")
    sweep.add_argument("-o", "--output", metavar="FILE", help="with 'plot': picture file (.png, .svg, .pdf)")
    sweep.add_argument("--kind", choices=["map", "curve"], help="with 'plot': success map over two parameters "
                                                                "or rate against one (default: map if 2+ parameters)")
    sweep.add_argument("--x", metavar="PARAMETER", help="with 'plot': parameter on the x axis (default the first)")
    sweep.add_argument("--y", metavar="PARAMETER", help="with 'plot': parameter on the y axis / per curve (default the second)")
    sweep.add_argument("--metric", metavar="NAME", help="with 'plot --kind map': colour by this metric's median "
                                                        "instead of the success rate")
    sweep.set_defaults(handler=command_sweep, plot_handler=plot_handler)
