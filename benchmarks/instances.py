"""instances: time per tick per graph instance from 1 to 100 instances, and from 1 to 100 worlds.

Graph: a small core-node graph built in code (OnTick, Counter, Branch on a
Compare, Add / Multiply math, WriteVariable, FlipFlop, Sequence; 12 nodes).
``Simulation(document, instances=N)`` for N = 1, 10, 100 in one ClockWorld,
and N separate Simulations (N worlds) in one process, all stepped in
interleaved rounds (each turn starts with 5 untimed ticks, so a candidate is
not timed while its data is still out of the caches the others used); figures
are CPU µs per instance-tick (median of rounds).
With the pick-and-place graph present, 1 and 4 PyBullet worlds running it are
compared the same way (µs per world-tick). Ratio = the worst of N=100 / N=1
per-instance time (instances or worlds): 1.00 is perfectly flat.
"""
from __future__ import annotations

from graphflow.document import parse_document
from graphflow.runtime import Simulation

from . import Skip, clock, interleaved, line, median, paired_ratio
from ._scenes import PICK_PLACE, simulation

COUNTS = (1, 10, 100)


def build_document():
    def conn(src, dst):
        return {"src": src, "dst": dst}

    return parse_document({
        "format": "graphflow", "formatVersion": [1, 0], "settings": {"timeStep": 1 / 60},
        "variables": [{"name": "total", "type": "double", "default": 0.0}],
        "nodes": [
            {"name": "tick", "type": "omni.graph.action.OnTick"},
            {"name": "sequence", "type": "omni.graph.action.Sequence"},
            {"name": "counter", "type": "omni.graph.action.Counter"},
            {"name": "even", "type": "omni.graph.action.FlipFlop"},
            {"name": "big", "type": "omni.graph.nodes.Compare", "inputs": {"b": 1000, "operation": ">"}},
            {"name": "branch", "type": "omni.graph.action.Branch"},
            {"name": "scaled", "type": "omni.graph.nodes.Multiply", "inputs": {"b": 0.5}},
            {"name": "offset", "type": "omni.graph.nodes.Add", "inputs": {"b": 2.0}},
            {"name": "write_low", "type": "omni.graph.core.WriteVariable", "inputs": {"variableName": "total"}},
            {"name": "write_high", "type": "omni.graph.core.WriteVariable", "inputs": {"variableName": "total"}},
            {"name": "high_value", "type": "omni.graph.nodes.ConstantDouble", "inputs": {"value": -1.0}},
            {"name": "time_scaled", "type": "omni.graph.nodes.Multiply", "inputs": {"b": 2.0}},
        ],
        "connections": [
            conn("tick.outputs:tick", "sequence.inputs:execIn"),
            conn("sequence.outputs:a", "counter.inputs:execIn"),
            conn("sequence.outputs:b", "even.inputs:execIn"),
            conn("counter.outputs:execOut", "branch.inputs:execIn"),
            conn("counter.outputs:count", "big.inputs:a"),
            conn("big.outputs:result", "branch.inputs:condition"),
            conn("counter.outputs:count", "scaled.inputs:a"),
            conn("scaled.outputs:product", "offset.inputs:a"),
            conn("branch.outputs:execFalse", "write_low.inputs:execIn"),
            conn("offset.outputs:sum", "write_low.inputs:value"),
            conn("branch.outputs:execTrue", "write_high.inputs:execIn"),
            conn("high_value.outputs:value", "write_high.inputs:value"),
            conn("tick.outputs:time", "time_scaled.inputs:a"),
        ],
    }, "<instances benchmark>")


def _stepper(simulations, ticks: int, warm_up: int = 0):
    """Step every simulation *ticks* times; returns the CPU seconds, not counting *warm_up* untimed ticks
    first (they bring this candidate's data back into the caches after the other candidates ran)."""
    def run() -> float:
        for _ in range(warm_up):
            for sim in simulations:
                sim.step()
        started = clock()
        for _ in range(ticks):
            for sim in simulations:
                sim.step()
        return clock() - started
    return run


def run(quick: bool = False) -> str:
    document = build_document()
    counts = (1, 10) if quick else COUNTS
    ticks, rounds, warm_up = (5, 3, 1) if quick else (40, 25, 5)
    candidates, per = {}, {}
    for n in counts:
        candidates[f"instances_{n}"] = _stepper([Simulation(document, instances=n)], ticks, warm_up)
        per[f"instances_{n}"] = n * ticks
        candidates[f"worlds_{n}"] = _stepper([Simulation(document) for _ in range(n)], ticks, warm_up)
        per[f"worlds_{n}"] = n * ticks
    for step in candidates.values():
        step()  # warm-up
    samples = interleaved(candidates, rounds)
    top = counts[-1]
    ratios = [paired_ratio([t / per[f"{kind}_{top}"] for t in samples[f"{kind}_{top}"]],
                           [t / per[f"{kind}_1"] for t in samples[f"{kind}_1"]]) for kind in ("instances", "worlds")]
    figures = {name: f"{median(times) / per[name] * 1e6:.2f}us" for name, times in samples.items()}
    print(f"instances: {len(document.nodes)}-node graph, {ticks} ticks x {rounds} interleaved rounds; "
          f"per instance-tick {top}/1: instances {ratios[0]:.2f}, worlds {ratios[1]:.2f}")
    if not quick:
        try:
            figures.update(_physics_worlds(ticks=60, rounds=5))
        except Skip as reason:
            print(f"instances: physics worlds skipped ({reason})")
    return line("instances", max(ratios), **figures)


def _physics_worlds(ticks: int, rounds: int) -> dict[str, str]:
    """1 and 4 PyBullet worlds each running the pick-and-place graph, per world-tick."""
    sims = {n: [simulation(PICK_PLACE) for _ in range(n)] for n in (1, 4)}
    try:
        samples = interleaved({n: _stepper(group, ticks, warm_up=5) for n, group in sims.items()}, rounds)
    finally:
        for group in sims.values():
            for sim in group:
                sim.close()
    per_world = {n: median(times) / (n * ticks) * 1e6 for n, times in samples.items()}
    ratio = paired_ratio([t / 4 for t in samples[4]], samples[1])
    print(f"instances: pick-and-place in 1 / 4 PyBullet worlds: {per_world[1]:.0f} / {per_world[4]:.0f} µs per world-tick "
          f"(4/1: {ratio:.2f})")
    return {"pick_place_worlds_1": f"{per_world[1]:.0f}us", "pick_place_worlds_4": f"{per_world[4]:.0f}us"}
