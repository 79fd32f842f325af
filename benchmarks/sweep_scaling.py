"""sweep_scaling: episodes per second of ``graphflow sweep`` on 1 and 2 pool workers, against one process per
episode, and on Ray against the pool.

Episodes: the first N of ``sweeps/force_limit_mass.json`` (the UR10 tuned pick-and-place, 18.8 s
simulated each, a randomized cube pose per seed, so every episode builds its world from the worker's
open stage). Figures are wall-clock (parallel workers are the point), start-up included: each
configuration runs the same episodes from a cold start (spawned workers import, parse the graph,
open the stage). ``per_process`` runs each episode as its own ``graphflow run --set ... --randomize
... --seed`` process, what a shell loop would do. Ray (if installed) runs the same episodes on a
local Ray started for the purpose; its start-up (to the first record, ``ray_start``) and its shut-down
(from the last record until ``ray.shutdown()`` returned, ``ray_stop``: 1 s of it is Ray's autoscaler
monitor, whose SIGTERM handler reports to the GCS, already stopped, until it is killed after 1 s) are
reported apart, and its overhead is the time from its first to its last record against the pool's
(both start their workers inside the clock and build one runner per worker), summed over two runs
of each in the order pool, Ray, Ray, pool. Targets: 2 workers at least 1.8x
one worker on a quiet machine; Ray at most 10 % slower than the pool. ``pyramid``: episodes of
``sweeps/pyramid_randomized.json`` per CPU second in a warm runner (target at least 1 per core). Ratio = wall(2 workers) /
wall(1 worker) (0.5 is perfect scaling). On a shared machine the wall figures follow the other
load; ``cpu_scaling`` (2 x CPU per episode on 1 worker / on 2 workers, from the joined workers'
rusage) is what two idle cores would give. ``--quick`` uses the core counter graph and 4 episodes.
"""
from __future__ import annotations

import json
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from . import GRAPHS, ROOT, Skip, line

SWEEP = ROOT / "sweeps" / "force_limit_mass.json"
PYRAMID = ROOT / "sweeps" / "pyramid_randomized.json"


def _children_cpu() -> float:
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def _timed(executor, episodes) -> tuple[float, float, float, list[dict], float]:
    """(wall seconds to the first record, to the last record, in all (shut-down included), records,
    CPU seconds of the joined workers)."""
    cpu = _children_cpu()
    started = time.perf_counter()
    first, last, records = None, None, []
    for record in executor.run(episodes):
        last = time.perf_counter() - started
        if first is None:
            first = last
        records.append(record)
    return first, last, time.perf_counter() - started, records, _children_cpu() - cpu


def _quick_sweep(folder: Path) -> Path:
    path = folder / "quick.json"
    path.write_text(json.dumps({"format": "graphflow-sweep", "formatVersion": [1, 0],
                                "graph": str(GRAPHS / "counter_branch_print.json"),
                                "grid": {"at_least_three.b": [2000, 2001, 2002, 2003]}, "ticks": 5000}))
    return path


def _pyramid_cpu_per_episode(count: int = 3) -> float:
    """CPU seconds per episode of the randomized pyramid sweep in one warm runner (the pool's steady state)."""
    from graphflow.sweep.definition import load_sweep
    from graphflow.sweep.episode import EpisodeRunner

    sweep = load_sweep(str(PYRAMID))
    runner = EpisodeRunner(sweep)
    try:
        runner.run(sweep.episodes()[0])   # warm-up: imports, first parse
        started = time.process_time()
        for episode in sweep.episodes()[1:count + 1]:
            runner.run(episode)
        return (time.process_time() - started) / count
    finally:
        runner.close()


def _per_process(sweep, episodes) -> float:
    """Wall seconds to run *episodes* as one ``graphflow run`` process each (the records' replay commands)."""
    started = time.perf_counter()
    for episode in episodes:
        command = [sys.executable, "-m", "graphflow", *sweep.replay_command(episode)[1:]]
        subprocess.run(command, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, cwd=ROOT)
    return time.perf_counter() - started


def run(quick: bool = False) -> str:
    from graphflow.sweep.definition import load_sweep
    from graphflow.sweep.launchers import LocalPool, RayPool

    with tempfile.TemporaryDirectory() as folder:
        if quick:
            sweep = load_sweep(str(_quick_sweep(Path(folder))))
        else:
            if not SWEEP.exists():
                raise Skip(f"{SWEEP.relative_to(ROOT)} not found")
            sweep = load_sweep(str(SWEEP))
        episodes = sweep.episodes()[: 4 if quick else 16]
        _first1, _last1, wall1, records1, cpu1 = _timed(LocalPool(sweep, 1), episodes)
        first2, last2, wall2, records2, cpu2 = _timed(LocalPool(sweep, 2), episodes)
        strip = lambda rows: sorted((r["key"], json.dumps({k: v for k, v in r.items() if k != "wall"})) for r in rows)
        if strip(records1) != strip(records2):
            raise RuntimeError("1 and 2 workers gave different records")
        process_episodes = episodes[:2 if quick else 4]
        per_process = _per_process(sweep, process_episodes) / len(process_episodes)
        n = len(episodes)
        figures = {"workers1": f"{n / wall1:.2f}ep/s", "workers2": f"{n / wall2:.2f}ep/s",
                   "speedup": f"{wall1 / wall2:.2f}x", "per_process": f"{1 / per_process:.2f}ep/s",
                   "reuse_gain": f"{per_process / (wall1 / n):.2f}x",
                   "cpu_per_episode": f"{cpu1 / n:.3f}s", "cpu_scaling": f"{2 * cpu1 / cpu2:.2f}x"}
        detail = (f"sweep_scaling: {n} episodes ({'counter graph' if quick else SWEEP.name}); wall s: 1 worker "
                  f"{wall1:.2f}, 2 workers {wall2:.2f} (target speedup >= 1.8 on a quiet machine); one process per "
                  f"episode {per_process:.2f} s each; workers' CPU s per episode (start-up included): 1 worker {cpu1 / n:.3f}, "
                  f"2 workers {cpu2 / n:.3f}, so 2 idle cores would give {2 * cpu1 / cpu2:.2f}x (wall figures suffer "
                  "from whatever else the machine runs; CPU figures do not)")
        try:
            import ray  # noqa: F401
        except ImportError:
            ray = None
        if ray is not None and not quick:
            # pool, Ray, Ray, pool: a load that rises or falls during the four runs hits both sides alike
            ray_runs = [_timed(RayPool(sweep, 2, None), episodes) for _ in range(2)]
            pool_runs = [(first2, last2, wall2, records2, cpu2), _timed(LocalPool(sweep, 2), episodes)]
            if any(strip(run[3]) != strip(records2) for run in ray_runs + pool_runs):
                raise RuntimeError("Ray and the pool gave different records")
            steady = lambda runs: sum(last - first for first, last, *_rest in runs)
            mean = lambda values: sum(values) / len(values)
            ray_start = mean([run[0] for run in ray_runs])
            ray_stop = mean([run[2] - run[1] for run in ray_runs])
            figures["ray"] = f"{n / mean([run[2] for run in ray_runs]):.2f}ep/s"
            figures["ray_start"] = f"{ray_start:.1f}s"
            figures["ray_stop"] = f"{ray_stop:.1f}s"
            figures["ray_overhead"] = f"{100 * (steady(ray_runs) / steady(pool_runs) - 1):+.0f}%"
            shown = lambda runs: ", ".join(f"{first:.2f} + {last - first:.2f} + {wall - last:.2f}"
                                           for first, last, wall, *_rest in runs)
            detail += (f"; Ray (2 actors) against the pool, run pool, Ray, Ray, pool, each as s to the first record "
                       f"+ first to last record + shut-down: Ray {shown(ray_runs)}, pool {shown(pool_runs)} "
                       "(records identical)")
        if not quick and PYRAMID.exists():
            pyramid_cpu = _pyramid_cpu_per_episode()
            figures["pyramid"] = f"{1 / pyramid_cpu:.2f}ep/s/core"
            detail += (f"; randomized pyramid (sweeps/{PYRAMID.name}): {pyramid_cpu:.2f} CPU s per episode, "
                       f"{1 / pyramid_cpu:.2f} episodes per second per core (target >= 1; Ravens oracle 0.135)")
        print(detail)
    return line("sweep_scaling", wall2 / wall1, **figures)
