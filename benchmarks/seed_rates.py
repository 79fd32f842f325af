"""seed_rates: an N-seed rate scenario (``graphflow test`` with ``"seeds": N``) against N separate
``graphflow run --seed S`` processes, in episodes per second.

The scenario is ``graphs/ur10_pick_place.json`` run as a rate over 50 seeds: its episodes go to the sweep
launcher's local workers, each of which parses the graph and opens the stage once and then resets its
simulation between episodes. The baseline starts one ``graphflow run GRAPH --seed S`` process per seed,
as many at a time as the rate has workers (what a shell loop with ``xargs -P`` does): each process
imports graphflow, opens the stage and builds its world. Both are wall-clock, start-up included, one run
each (the rate first). Ratio = wall(rate) / wall(processes), lower is better. ``--quick``: 4 seeds of
``graphs/counter_branch_print.json``.
"""
from __future__ import annotations

import os
import subprocess
import sys
import time

from . import GRAPHS, ROOT, line


def _rate(path: str, seeds: int, jobs: int) -> tuple[float, int]:
    from graphflow.sweep.scenario_rates import run_rate
    from graphflow.verdicts.rates import RatePlan

    started = time.perf_counter()
    verdict = run_rate(RatePlan(path, list(range(seeds)), gate=0.0, confidence=0.95), jobs=jobs)
    return time.perf_counter() - started, verdict.runs


def _processes(path: str, seeds: int, jobs: int) -> float:
    started = time.perf_counter()
    waiting = list(range(seeds))
    running: list[subprocess.Popen] = []
    while waiting or running:
        while waiting and len(running) < jobs:
            seed = waiting.pop(0)
            running.append(subprocess.Popen([sys.executable, "-m", "graphflow", "run", path, "--seed", str(seed)],
                                            cwd=ROOT, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL))
        running[0].wait()
        running = [process for process in running if process.poll() is None]
    return time.perf_counter() - started


def run(quick: bool = False) -> str:
    graph = GRAPHS / ("counter_branch_print.json" if quick else "ur10_pick_place.json")
    seeds = 4 if quick else 50
    jobs = min(2, os.cpu_count() or 1)
    rate_wall, runs = _rate(str(graph), seeds, jobs)
    process_wall = _processes(str(graph), seeds, jobs)
    print(f"  {graph.name}, {seeds} seeds on {jobs} workers: rate {rate_wall:.1f} s ({runs / rate_wall:.2f} episodes/s), "
          f"separate processes {process_wall:.1f} s ({seeds / process_wall:.2f} episodes/s)", flush=True)
    return line("seed_rates", rate_wall / process_wall, rate_eps=f"{runs / rate_wall:.2f}/s",
                processes_eps=f"{seeds / process_wall:.2f}/s", speedup=f"{process_wall / rate_wall:.2f}x")
