"""A sweep file read and checked: its graph, its grid / samples of overrides, its seeds, its episodes.

Format: docs/sweeps.md; schema: graphflow/schema/sweep.schema.json. Every override and metric prim is
checked before anything runs, so a sweep never fails on its hundredth episode for a typo.
"""
from __future__ import annotations

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
    RandomizationError,
    draw,
    parse_randomization,
    schema_problems,
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
    """Read, schema-check and resolve a sweep file; every override is checked before anything runs."""
    data = read_json(path)
    problems = schema_problems(data, path)
    if problems:
        raise SweepError(problems[0])
    if data["formatVersion"][0] != 1:
        raise SweepError(f"{path}: formatVersion {data['formatVersion']} is not supported (this runtime reads 1.x)")
    graph_path = Path(path).resolve().parent / data["graph"]
    graph_data = read_json(graph_path)
    sweep = Sweep(data, path, graph_data, str(graph_path))
    _check(sweep)
    return sweep


def _check(sweep: Sweep) -> None:
    """Fail before any episode runs: the graph, conflicting targets, and every point's overrides."""
    from graphflow.document import GraphError, parse_document

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
                    stage = Variant(document, tuple(stage_edits)).open_stage()
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
            stage = Variant(document, ()).open_stage()
        for path in paths:
            if not stage.GetPrimAtPath(path):
                raise SweepError(f"{sweep.source}: metrics/{index} ({metric['name']}): the stage has no prim {path}")
