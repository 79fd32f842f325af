"""dispatch: the executor's cost per node against the same computes called inline.

The graph (a document built in code): OnTick pulses a chain of 10
WriteVariable nodes; each pulls its value through a chain of 99 Add nodes
(``a`` from the previous Add, ``b`` authored), 1,001 nodes in all. The baseline
is a hand-written loop over the same compute functions with the same node
databases: copy the input, call compute, nothing else. Figures: µs per node per
tick for both (median CPU time of 75 interleaved rounds of 40 ticks), ratio =
median of the per-round ratios.
"""
from __future__ import annotations

from graphflow.document import parse_document
from graphflow.registry import default_registry
from graphflow.runtime import Simulation
from graphflow.types import ExecState

from . import interleaved, line, median, paired_ratio

CHAINS = 10
ADDS_PER_CHAIN = 99


def build_document(chains: int = CHAINS, adds: int = ADDS_PER_CHAIN):
    nodes = [{"name": "tick", "type": "omni.graph.action.OnTick"}]
    connections = []
    variables = []
    previous_exec = "tick.outputs:tick"
    for c in range(chains):
        for k in range(adds):
            inputs = {"b": 1.0} if k else {"a": float(c), "b": 1.0}
            nodes.append({"name": f"add_{c}_{k}", "type": "omni.graph.nodes.Add", "inputs": inputs})
            if k:
                connections.append({"src": f"add_{c}_{k - 1}.outputs:sum", "dst": f"add_{c}_{k}.inputs:a"})
        writer = f"write_{c}"
        variables.append({"name": f"v{c}", "type": "double", "default": 0.0})
        nodes.append({"name": writer, "type": "omni.graph.core.WriteVariable", "inputs": {"variableName": f"v{c}"}})
        connections.append({"src": f"add_{c}_{adds - 1}.outputs:sum", "dst": f"{writer}.inputs:value"})
        connections.append({"src": previous_exec, "dst": f"{writer}.inputs:execIn"})
        previous_exec = f"{writer}.outputs:execOut"
    return parse_document({"format": "graphflow", "formatVersion": [1, 0], "settings": {"timeStep": 1 / 240},
                           "variables": variables, "nodes": nodes, "connections": connections}, "<dispatch benchmark>")


def inline_loop(simulation: Simulation, chains: int = CHAINS, adds: int = ADDS_PER_CHAIN):
    """The baseline: a hand-written tick calling the same computes on the same kind of databases."""
    instance = simulation.instance
    registry = default_registry()
    on_tick = registry.get("omni.graph.action.OnTick").compute
    add = registry.get("omni.graph.nodes.Add").compute
    write = registry.get("omni.graph.core.WriteVariable").compute
    tick_db = instance.database("tick")
    plan = [([instance.database(f"add_{c}_{k}") for k in range(adds)], instance.database(f"write_{c}"))
            for c in range(chains)]
    enabled, disabled = ExecState.ENABLED, ExecState.DISABLED

    def tick():
        instance.tick_count += 1
        tick_db.outputs.tick = disabled
        on_tick(tick_db)
        for chain, writer in plan:
            first = chain[0]
            add(first)
            previous = first.outputs
            for database in chain[1:]:
                database.inputs.a = previous.sum
                add(database)
                previous = database.outputs
            writer.inputs.value = previous.sum
            writer.inputs.execIn = enabled
            writer.outputs.execOut = disabled
            write(writer)

    return tick


def run(quick: bool = False) -> str:
    chains, adds = (2, 9) if quick else (CHAINS, ADDS_PER_CHAIN)
    ticks, rounds = (20, 3) if quick else (40, 75)
    document = build_document(chains, adds)
    graph, baseline = Simulation(document), Simulation(document)
    inline_tick = inline_loop(baseline, chains, adds)
    baseline_world = baseline.world

    def run_graph():
        step = graph.step
        for _ in range(ticks):
            step()

    def run_baseline():
        step = baseline_world.step
        for _ in range(ticks):
            step()
            inline_tick()

    run_graph(), run_baseline()   # warm-up
    samples = interleaved({"graphflow": run_graph, "baseline": run_baseline}, rounds)
    expected = baseline.instance.variables
    assert graph.instance.variables == expected, (graph.instance.variables, expected)
    count = len(document.nodes)
    per_node = {name: median(times) / ticks / count * 1e6 for name, times in samples.items()}
    print(f"dispatch: {count} nodes, {ticks} ticks x {rounds} interleaved rounds; "
          f"graphflow {per_node['graphflow'] * count:.0f} µs/tick, baseline {per_node['baseline'] * count:.0f} µs/tick")
    return line("dispatch", paired_ratio(samples["graphflow"], samples["baseline"]),
                graphflow=f"{per_node['graphflow']:.3f}us/node", baseline=f"{per_node['baseline']:.3f}us/node",
                nodes=f"{count}", ticks=f"{ticks * rounds}")
