"""graphflow benchmarks: what the runtime costs beyond physics, measured side by side.

Machines are shared and noisy, so every figure is a ratio of graphflow to a
baseline measured in the same run: short repetitions of the two are
interleaved (the order alternates every round), each round gives one ratio and
the reported ratio is the median of those. In-process timings use the process
CPU clock (``time.process_time``), so time spent descheduled by other
processes on the machine does not count; wall-clock figures say so. Each benchmark module
has ``run(quick: bool) -> str``; it may print detail lines and returns its final
line, ``NAME: ratio=R.RR key=VALUEunit ...`` (ratio = graphflow / baseline,
lower is better). ``python -m benchmarks [NAME] [--quick]`` runs them.

``--quick`` is a tiny configuration that only proves a benchmark works (the
test suite runs it); its figures mean little.
"""
from __future__ import annotations

import os
import platform
import statistics
import sys
import time
from pathlib import Path
from typing import Callable

ROOT = Path(__file__).resolve().parent.parent
GRAPHS = ROOT / "graphs"

NAMES = ("dispatch", "pick_place_overhead", "plain_pybullet", "realtime", "finished_controllers", "instances", "startup",
         "memory", "sweep_scaling", "report", "seed_rates")


class Skip(Exception):
    """The benchmark cannot run here (a graph it needs is missing); the message says why."""


clock = time.process_time


def interleaved(candidates: dict[str, Callable[[], float | None]], rounds: int) -> dict[str, list[float]]:
    """Run every candidate once per round, alternating the order each round.

    A candidate returns the seconds it measured itself (with ``clock``), or
    None to be timed whole. Returns the samples of every candidate.
    """
    samples: dict[str, list[float]] = {name: [] for name in candidates}
    names = list(candidates)
    for round_index in range(rounds):
        order = names if round_index % 2 == 0 else names[::-1]
        for name in order:
            started = clock()
            measured = candidates[name]()
            samples[name].append(measured if measured is not None else clock() - started)
    return samples


def median(values) -> float:
    return statistics.median(values)


def paired_ratio(numerators: list[float], denominators: list[float]) -> float:
    """Median of the per-round ratios: a burst of load hits both sides of one round alike."""
    return statistics.median(a / b for a, b in zip(numerators, denominators))


def line(name: str, ratio: float, **figures: str) -> str:
    """The final line of a benchmark: ``NAME: ratio=R.RR key=value ...``."""
    return f"{name}: ratio={ratio:.2f}" + "".join(f" {key}={value}" for key, value in figures.items())


def rss_mb() -> float:
    """Resident set size of this process, MB (VmRSS from /proc/self/status, else ru_maxrss)."""
    try:
        with open("/proc/self/status", encoding="ascii") as status:
            for text in status:
                if text.startswith("VmRSS:"):
                    return int(text.split()[1]) / 1024.0
    except OSError:
        pass
    import resource

    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0


def machine() -> str:
    """nproc, CPU model and Python version, for the README and the detail lines."""
    model = platform.processor() or "unknown CPU"
    try:
        with open("/proc/cpuinfo", encoding="utf-8") as cpuinfo:
            for text in cpuinfo:
                if text.startswith("model name"):
                    model = text.split(":", 1)[1].strip()
                    break
    except OSError:
        pass
    return f"nproc {os.cpu_count()}, {model}, Python {platform.python_version()} ({sys.implementation.name})"
