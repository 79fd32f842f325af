"""memory: resident memory after 1,000,000 ticks of a core-node graph, against after warm-up.

Graph: graphs/counter_branch_print.json, stepped past its StopRun (from tick 3
on it logs a line every tick, so the event log fills to its cap of 10,000 lines
during the 20,000 warm-up ticks). RSS (VmRSS) is read after the warm-up and
after the timed ticks; target: less than 5 MB of growth. Ratio = RSS after /
RSS after warm-up. ``--quick``: 1,000 + 2,000 ticks.
"""
from __future__ import annotations

import gc

from graphflow.document import load_document
from graphflow.runtime import Simulation

from . import GRAPHS, ROOT, Skip, clock, line, rss_mb

GRAPH = GRAPHS / "counter_branch_print.json"


def run(quick: bool = False) -> str:
    if not GRAPH.exists():
        raise Skip(f"{GRAPH.relative_to(ROOT)} not found")
    warm_up, ticks = (1_000, 2_000) if quick else (20_000, 1_000_000)
    sim = Simulation(load_document(GRAPH))
    step = sim.step
    for _ in range(warm_up):
        step()
    gc.collect()
    before = rss_mb()
    started = clock()
    for _ in range(ticks):
        step()
    elapsed = clock() - started
    gc.collect()
    after = rss_mb()
    growth = after - before
    print(f"memory: {GRAPH.name}, {warm_up} warm-up + {ticks} ticks ({elapsed / ticks * 1e6:.1f} µs/tick CPU); "
          f"RSS {before:.1f} -> {after:.1f} MB, growth {growth:+.2f} MB (target < 5 MB); "
          f"event log {len(sim.instance.events)} lines")
    return line("memory", after / before, growth=f"{growth:+.2f}MB", rss=f"{after:.1f}MB", ticks=f"{ticks}")
