"""finished_controllers: what pick-and-place controllers cost per tick once their routine is done.

A graph that chains controllers (one per object, as an Isaac graph does) keeps pulsing the
finished ones every tick. graphflow: OnTick pulsing six PickPlaceControllers on the UR10 pick-and-place
stage, each pulling the cube's pose from its own ReadPrimPose, all six finished (they run
their ten phases in ten ticks first, with every phase increment 1.0). Baseline: the same stage with a
graph of the OnTick alone, so the ratio is what six finished controllers add to a tick that
steps the same world (1.00: they cost nothing). Both are interleaved in chunks of ticks.
"""
from __future__ import annotations

from . import clock, line, paired_ratio
from ._scenes import quiet

CONTROLLERS = 6
ROBOT, GRIPPER, CUBE = "/World/ur10", "/World/ur10/ee_link/SurfaceGripper", "/World/Cube"


def _graph(controllers: int) -> dict:
    nodes = [{"name": "tick", "type": "omni.graph.action.OnTick"}]
    connections = []
    for index in range(controllers):
        nodes += [{"name": f"cube_pose_{index}", "type": "graphflow.ReadPrimPose", "inputs": {"prim": CUBE}},
                  {"name": f"pick_place_{index}", "type": "graphflow.PickPlaceController",
                   "inputs": {"robotPrim": ROBOT, "gripperPrim": GRIPPER, "placingPosition": [0.7, 0.7, 0.02575],
                              "eventsDT": [1.0] * 10}}]
        connections += [{"src": "tick.outputs:tick", "dst": f"pick_place_{index}.inputs:execIn"},
                        {"src": f"cube_pose_{index}.outputs:position",
                         "dst": f"pick_place_{index}.inputs:pickingPosition"}]
    return {"format": "graphflow", "formatVersion": [1, 0], "settings": {"stage": "asset:ur10_pick_place.usda"},
            "nodes": nodes, "connections": connections}


def _simulation(controllers: int):
    from graphflow.document import parse_document
    from graphflow.runtime import Simulation

    with quiet():
        return Simulation(parse_document(_graph(controllers), "finished_controllers.json"))


def run(quick: bool = False) -> str:
    chained, alone = _simulation(CONTROLLERS), _simulation(0)
    ticks, chunk = (40, 20) if quick else (3000, 100)
    try:
        for sim in (chained, alone):
            sim.run(ticks=20)            # ten phases of one tick each, then done
        done = [chained.instance.database(f"pick_place_{i}").outputs.isDone for i in range(CONTROLLERS)]
        if not all(done):
            raise AssertionError(f"the controllers did not finish: {done}")
        samples = {"chained": [], "alone": []}
        for start in range(0, ticks, chunk):
            order = ("chained", "alone") if (start // chunk) % 2 else ("alone", "chained")
            for name in order:
                step = (chained if name == "chained" else alone).step
                started = clock()
                for _ in range(chunk):
                    step()
                samples[name].append(clock() - started)
    finally:
        chained.close()
        alone.close()
    per_tick = {name: sum(times) / ticks * 1e6 for name, times in samples.items()}
    extra = (per_tick["chained"] - per_tick["alone"]) / CONTROLLERS
    print(f"finished_controllers: {ticks} ticks interleaved in chunks of {chunk}; {CONTROLLERS} finished controllers "
          f"{per_tick['chained']:.1f} µs/tick against the OnTick alone {per_tick['alone']:.1f} µs/tick "
          f"({extra:.2f} µs per finished controller per tick, CPU time)")
    return line("finished_controllers", paired_ratio(samples["chained"], samples["alone"]),
                chained=f"{per_tick['chained']:.1f}us/tick", alone=f"{per_tick['alone']:.1f}us/tick",
                per_controller=f"{extra:.2f}us")
