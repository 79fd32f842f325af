"""A sweep file read and checked: its graph, its grid / samples of overrides, its seeds, its episodes.

Format: docs/sweeps.md; schema: graphflow/schema/sweep.schema.json. Every override and metric prim is
checked before anything runs, so a sweep never fails on its hundredth episode for a typo.
"""
from __future__ import annotations

import dataclasses
import json
from dataclasses import dataclass
from itertools import product
from pathlib import Path
from typing import Any, Mapping

from graphflow.errors import BadInput
from graphflow.files import read_json
from graphflow.variants.overrides import (
    Override,
    OverrideError,
    PoseJitter,
    Variant,
    apply_node_overrides,
    apply_stage_overrides,
)
from graphflow.variants.randomize import (
    draw,
    entry_problems,
    parse_randomization,
    schema_errors,
    stream,
)

SWEEP_FORMAT = "graphflow-sweep"
EPISODES_JSONL, EPISODES_CSV = "episodes.jsonl", "episodes.csv"
SUMMARY_CSV, SUMMARY_JSON, MANIFEST = "summary.csv", "summary.json", "sweep.json"


class SweepError(BadInput):
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


def load_sweep(path: str) -> Sweep:
    """Read, schema-check and resolve a sweep file; every problem of it at once, before anything runs.

    A schema problem does not hide the rest: the sections the schema accepted (the graph, the other
    overrides, the metrics) are still checked against the graph and its stage.
    """
    data = read_json(path)
    errors = schema_errors(data, path)
    problems = [line for _where, line in errors]
    broken = {where[0] for where, _line in errors if where}
    if not isinstance(data, dict) or not isinstance(data.get("graph"), str) or broken & {"graph", "formatVersion"}:
        raise SweepError("\n".join(problems))     # nothing further can be checked without the graph
    if data.get("formatVersion", [1])[0] != 1:
        raise SweepError(f"{path}: formatVersion {data['formatVersion']} is not supported (this runtime reads 1.x)")
    graph_path = Path(path).resolve().parent / data["graph"]
    graph_data = read_json(graph_path)
    usable = {key: value for key, value in data.items() if key not in broken or key == "randomize"}
    randomize = data.get("randomize", [])
    broken_entries = {where[1] for where, _line in errors if len(where) >= 2 and where[0] == "randomize"}
    if not isinstance(randomize, list):
        randomize, broken_entries = [], set()
    sweep = Sweep(usable, path, graph_data, str(graph_path))
    problems += _problems(sweep, randomize, broken_entries)
    if problems:
        raise SweepError("\n".join(problems))
    return Sweep(data, path, graph_data, str(graph_path))


def check_sweep(sweep: Sweep) -> None:
    """Refuse a sweep built in memory (a rate scenario's) as a sweep file is refused: every problem at once."""
    randomize = sweep.data.get("randomize", [])
    problems = _problems(sweep, randomize if isinstance(randomize, list) else [], set())
    if problems:
        raise SweepError("\n".join(problems))


def _problems(sweep: Sweep, randomize: list, broken_entries: set) -> list[str]:
    """Every problem found before any episode runs: the graph, conflicting targets, each override, the metrics."""
    from graphflow.document import GraphError, parse_document

    try:
        document = parse_document(json.loads(json.dumps(sweep.graph_data)), sweep.graph_source)
    except GraphError as error:
        return [str(problem) for problem in error.problems]
    problems: list[str] = []
    kept = []
    for index, entry in enumerate(randomize):
        if index not in broken_entries:
            found = entry_problems(entry, f"{sweep.source}: randomize/{index}")
            problems += found
            kept += [] if found else [entry]
    sweep = dataclasses.replace(sweep, data={**sweep.data, "randomize": kept})   # the rest checked without them
    randomization = sweep.randomization()
    swept = set(sweep.parameter_names) | set(sweep.data.get("set", {}))
    for target in randomization.targets:
        if target in swept:
            problems.append(f"{sweep.source}: {target} is both swept (set/grid/samples) and randomized; "
                            "the randomized value would hide the swept one")
    grid, samples = sweep.data.get("grid", {}), sweep.data.get("samples", {}).get("parameters", {})
    fixed = sweep.data.get("set", {})
    for target in [*grid, *samples]:
        if (target in grid and target in samples) or target in fixed:
            problems.append(f"{sweep.source}: {target} appears twice (in two of set, grid and samples)")
    names = sweep.metric_names
    problems += [f"{sweep.source}: metrics: the name {name!r} is used twice"
                 for name in dict.fromkeys(names) if names.count(name) > 1]
    try:
        from graphflow.verdicts.checked_run import ScriptedInputs
        ScriptedInputs.of_document(document)     # the scenario's inputs every episode attaches
    except BadInput as error:
        problems += error.lines()
    stage = _StageForChecks(document)
    problems += _override_problems(sweep, document, stage)
    problems += _metric_prim_problems(sweep, document, stage)
    return problems


class _StageForChecks:
    """The graph's stage opened once for the checks; each edit is tried on a cleared session layer."""

    def __init__(self, document):
        self.document, self.stage = document, None

    def fresh(self):
        if self.stage is None:
            self.stage = Variant(self.document, ()).open_stage()
        else:
            self.stage.GetSessionLayer().Clear()
        return self.stage


def _override_problems(sweep: Sweep, document, stage: _StageForChecks) -> list[str]:
    """Each distinct override alone (so every bad one is named with its own reason), then each point's together."""
    problems: list[str] = []
    episodes = sweep.episodes()
    first_of_point = sorted({e.point: e for e in reversed(episodes)}.values(), key=lambda e: e.index)
    alone: dict[str, Override | PoseJitter] = {}
    for episode in first_of_point:
        for edit in sweep.edits(episode):
            alone.setdefault(edit.label, edit)
    for edit in alone.values():
        try:
            if edit.on_stage:
                apply_stage_overrides(stage.fresh(), [edit])
            else:
                apply_node_overrides(document, [edit])
        except OverrideError as error:
            problems.append(str(error))
    if problems:
        return problems
    try:
        for episode in first_of_point:
            edits = sweep.edits(episode)
            apply_node_overrides(document, edits)
            stage_edits = [e for e in edits if e.on_stage]
            if stage_edits:
                apply_stage_overrides(stage.fresh(), stage_edits)
    except OverrideError as error:
        problems.append(str(error))
    return problems


def _metric_prim_problems(sweep: Sweep, document, stage: _StageForChecks) -> list[str]:
    """Every prim a metric names must be on the stage (else every episode would fail the same way)."""
    problems = []
    for index, metric in enumerate(sweep.data.get("metrics", [])):
        kind, spec = next((k, v) for k, v in metric.items() if k != "name")
        paths = [spec[key] for key in ("prim", "relativeTo", "gripper") if key in spec]
        if kind == "timeToFinish":
            continue
        if document.settings.get("stage") is None:
            problems.append(f"{sweep.source}: metrics/{index} ({metric['name']}): {kind} needs a graph with a stage")
            continue
        usd_stage = stage.fresh()
        problems += [f"{sweep.source}: metrics/{index} ({metric['name']}): the stage has no prim {path}"
                     for path in paths if not usd_stage.GetPrimAtPath(path)]
    return problems
