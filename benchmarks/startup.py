"""startup: from process start to the first tick of ``graphflow run``, and ``import graphflow`` alone.

Three child processes, interleaved over rounds: ``python -c pass`` (the
baseline: interpreter start), ``python -c "import graphflow"``, and ``graphflow
run graphs/counter_branch_print.json --ticks 1`` (the console script's code:
``graphflow.cli.main``; it loads, validates, compiles and ticks the core demo
once, then exits). Figures: the median wall seconds beyond interpreter start
(wall, not CPU: numpy's BLAS threads burn CPU while it imports; the children's
CPU time is printed too). Target: the run costs at most 0.5 s beyond
interpreter start. Ratio = run / python.
"""
from __future__ import annotations

import os
import subprocess
import sys
import time

from . import GRAPHS, ROOT, Skip, line, median

GRAPH = GRAPHS / "counter_branch_print.json"
COMMANDS = {
    "python": [sys.executable, "-c", "pass"],
    "import": [sys.executable, "-c", "import graphflow"],
    "run": [sys.executable, "-c", "import sys; from graphflow.cli import main; sys.exit(main())",
            "run", str(GRAPH), "--ticks", "1"],
}


def child_times(command: list[str]) -> tuple[float, float]:
    """(CPU seconds, wall seconds) of one child process."""
    started = time.perf_counter()
    process = subprocess.Popen(command, cwd=ROOT, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    _pid, status, usage = os.wait4(process.pid, 0)
    wall = time.perf_counter() - started
    process.returncode = os.waitstatus_to_exitcode(status)
    error = process.stderr.read().decode(errors="replace")
    process.stderr.close()
    if process.returncode != 0:
        raise RuntimeError(f"{' '.join(command[-5:])} failed ({process.returncode}): {error.strip()}")
    return usage.ru_utime + usage.ru_stime, wall


def run(quick: bool = False) -> str:
    if not GRAPH.exists():
        raise Skip(f"{GRAPH.relative_to(ROOT)} not found")
    rounds, warm_up = (1, 0) if quick else (15, 1)
    cpu = {name: [] for name in COMMANDS}
    wall = {name: [] for name in COMMANDS}
    names = list(COMMANDS)
    for round_index in range(warm_up + rounds):   # the warm-up round fills the file cache and is dropped
        for name in names if round_index % 2 else names[::-1]:
            seconds, elapsed = child_times(COMMANDS[name])
            if round_index >= warm_up:
                cpu[name].append(seconds)
                wall[name].append(elapsed)
    python = median(wall["python"])
    beyond = {name: median(wall[name]) - python for name in ("import", "run")}
    cpu_python = median(cpu["python"])
    print(f"startup: {rounds} interleaved rounds; wall s beyond interpreter start ({python:.3f} s): "
          f"import {beyond['import']:.3f}, run {beyond['run']:.3f} (target <= 0.5); CPU s beyond ({cpu_python:.3f} s; "
          f"numpy's BLAS threads count here): import {median(cpu['import']) - cpu_python:.3f}, "
          f"run {median(cpu['run']) - cpu_python:.3f}")
    return line("startup", median(wall["run"]) / python, **{
        "run": f"+{max(beyond['run'], 0.0):.3f}s", "import": f"+{max(beyond['import'], 0.0):.3f}s",
        "python": f"{python:.3f}s"})
