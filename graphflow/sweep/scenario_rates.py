"""A rate scenario's episodes on the sweep launchers: the scenario as an in-memory sweep of its seeds.

``graphflow.verdicts.rates`` plans a rate and judges it; running many episodes with one loaded stage per
worker is the sweep package's job, so ``graphflow test`` (through the command line) and the pytest plugin
(through ``graphflow test`` in a subprocess) reach the launchers here.
"""
from __future__ import annotations

import os

from graphflow.files import read_json
from graphflow.sweep.definition import Sweep, check_sweep
from graphflow.sweep.launchers import LocalPool, RayPool
from graphflow.verdicts.rates import RatePlan, RateVerdict


def scenario_sweep(plan: RatePlan):
    """The scenario as an in-memory sweep: no grid, its randomization, its seeds; checked as sweeps are."""
    graph_data = read_json(plan.path)
    data = {"format": "graphflow-sweep", "formatVersion": [1, 0], "graph": plan.path,
            "randomize": graph_data.get("scenario", {}).get("randomize", []),
            "seeds": {"start": plan.seeds[0], "count": len(plan.seeds)}}
    sweep = Sweep(data, plan.path, graph_data, plan.path)
    check_sweep(sweep)   # SweepError (bad input) for a randomization that cannot be drawn or applied
    return sweep


def run_rate(plan: RatePlan, *, jobs: int | None = None, ray: bool = False) -> RateVerdict:
    """Run the plan's episodes on the sweep launchers; every episode's record is kept (in seed order)."""
    sweep = scenario_sweep(plan)
    episodes = sweep.episodes()
    launcher = RayPool(sweep, jobs, None) if ray else LocalPool(sweep, min(jobs or os.cpu_count() or 1, len(episodes)))
    records = sorted(launcher.run(episodes), key=lambda record: record["seed"])
    expect = tuple(read_json(plan.path).get("scenario", {}).get("expectFailure", ()))
    return RateVerdict(plan.path, plan, records, expect_failure=expect)
