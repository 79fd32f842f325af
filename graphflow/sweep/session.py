"""``graphflow sweep run``: expand the sweep, run the episodes on a launcher, keep the results, summarize.

Records are appended to ``episodes.jsonl`` and ``episodes.csv`` in ``--out DIR`` as episodes finish;
``--resume`` runs only the episodes the folder lacks; ``sweep.json`` there keeps the sweep and graph the
folder was started with, so a changed sweep is refused.
"""
from __future__ import annotations

import os
import sys
import time
from pathlib import Path
from typing import Generator

from graphflow.errors import EXIT_INTERRUPTED, interrupt_handled
from graphflow.sweep.definition import EPISODES_CSV, SUMMARY_CSV, load_sweep
from graphflow.sweep.launchers import LocalPool, RayPool
from graphflow.sweep.results import (
    ResultsFolder,
    summarize,
    summary_lines,
    write_summary,
)

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
    """``graphflow sweep``: 0 when every episode ran (whatever their verdicts), 130 when interrupted (as Ctrl-C anywhere)."""
    sweep = load_sweep(path)
    folder = ResultsFolder(Path(out) if out else default_out(path), sweep)
    episodes = sweep.episodes()
    executor: LocalPool | RayPool
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
    nothing_to_run: tuple[dict, ...] = ()
    running: Generator[dict, None, None] = executor.run(todo) if todo else (record for record in nothing_to_run)
    try:
        for record in running:
            folder.append(record)
            records.append(record)
            bar.update(record)
    except KeyboardInterrupt:
        interrupted = True
        interrupt_handled()   # the summary of the kept episodes is written on purpose
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
        return EXIT_INTERRUPTED
    return 0
