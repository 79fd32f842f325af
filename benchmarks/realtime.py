"""realtime: simulated seconds per second for the headless demo graphs, against physics alone.

Scenes: graphs/ur10_pick_place.json, graphs/ur10_stacking.json (each runs until
it stops itself) and graphs/gantry_keyboard.json with its scripted keys
(gantry_keyboard.keys.json; it stops on the scripted Escape). graphflow: the
graph's ``Simulation.step()``; baseline: ``world.step()`` of the same stage
with no graph, for the same number of ticks, interleaved with it in chunks of
25 ticks. Speed = simulated seconds / CPU seconds of the graph run (CPU time is
wall time on an idle core; the wall-clock speed is printed too). Ratio = median
over all chunks of graph time / physics-only time: what the graph, its
controllers (IK) and the gripper service cost on top of stepping the world.
"""
from __future__ import annotations

import time

from . import Skip, clock, line, paired_ratio
from ._scenes import GANTRY, GANTRY_KEYS, PICK_PLACE, STACKING, attach_keys, bare_world, simulation

SCENES = (("pick_place", PICK_PLACE, None), ("stacking", STACKING, None), ("gantry", GANTRY, GANTRY_KEYS))
TARGETS = {"pick_place": 100.0, "stacking": 50.0}


def measure(path, keys, limit: int | None, chunk: int = 25):
    """(ticks, simulated seconds, graph CPU s, graph wall s, per-chunk graph times, per-chunk physics times)."""
    sim = simulation(path, keys)
    world = bare_world(path, keys)
    try:
        ticks = sim.run(ticks=limit, seconds=sim.document.settings.get("duration")).ticks
        sim.reset()
        world.reset()
        if keys is not None:     # fresh timelines for the timed run
            attach_keys(sim.world, keys)
            attach_keys(world, keys)
        graph_times, world_times, wall = [], [], 0.0
        for start in range(0, ticks, chunk):
            count = min(chunk, ticks - start)
            for name in (("graph", "world") if (start // chunk) % 2 else ("world", "graph")):
                step = sim.step if name == "graph" else world.step
                started, wall_started = clock(), time.perf_counter()
                for _ in range(count):
                    step()
                (graph_times if name == "graph" else world_times).append(clock() - started)
                if name == "graph":
                    wall += time.perf_counter() - wall_started
        return ticks, ticks * sim.world.time_step, sum(graph_times), wall, graph_times, world_times
    finally:
        sim.close()
        world.close()


def run(quick: bool = False) -> str:
    limit = 10 if quick else None
    figures, all_graph, all_world = {}, [], []
    for name, path, keys in SCENES:
        try:
            ticks, simulated, cpu, wall, graph_times, world_times = measure(path, keys, limit)
        except Skip as reason:
            print(f"realtime: {name} skipped ({reason})")
            continue
        all_graph += graph_times
        all_world += world_times
        speed = simulated / cpu
        figures[name] = f"{speed:.0f}x"
        target = f" (target >= {TARGETS[name]:.0f}x)" if name in TARGETS else ""
        print(f"realtime: {name}: {ticks} ticks, {simulated:.2f} s simulated in {cpu:.2f} s CPU ({speed:.0f}x{target}), "
              f"{wall:.2f} s wall ({simulated / wall:.0f}x); physics alone {sum(world_times):.2f} s CPU")
    if not figures:
        raise Skip("none of the demo graphs is present")
    return line("realtime", paired_ratio(all_graph, all_world), **figures)
