"""Multigate and SyncGate on the behaviour Kit's node reference describes."""
from graphflow.testing import GraphHarness


def _graph(*nodes, connections=()):
    return {"format": "graphflow", "formatVersion": [1, 0], "nodes": list(nodes),
            "connections": [{"src": s, "dst": d} for s, d in connections]}


def _counter(name):
    return {"name": name, "type": "omni.graph.action.Counter"}


def test_multigate_cycles_through_the_wired_outputs_and_reset_restarts_at_output0():
    harness = GraphHarness(_graph(
        {"name": "tick", "type": "omni.graph.action.OnTick"},
        {"name": "gate", "type": "omni.graph.action.Multigate"},
        _counter("first"), _counter("second"), _counter("third"),
        connections=[("tick.outputs:tick", "gate.inputs:execIn"), ("gate.outputs:output0", "first.inputs:execIn"),
                     ("gate.outputs:output1", "second.inputs:execIn"), ("gate.outputs:output2", "third.inputs:execIn")]))
    counts = []
    for _ in range(7):
        harness.run(1)
        counts.append(tuple(harness.output(name, "count") for name in ("first", "second", "third")))
    # outputs 0 1 2 0 1 2 0: three wired outputs, so output3..7 are never fired
    assert counts == [(1, 0, 0), (1, 1, 0), (1, 1, 1), (2, 1, 1), (2, 2, 1), (2, 2, 2), (3, 2, 2)]
    harness.instance.compute_node("gate", ("reset",))     # a reset alone fires nothing ...
    harness.run(1)                                        # ... and the next execIn fires output0, not output1
    assert tuple(harness.output(name, "count") for name in ("first", "second", "third")) == (4, 2, 2)


def _sync_graph(sync_source):
    """A tick fans out to two chains (left first, then right) that both end in the gate's execIn."""
    return _graph(
        {"name": "tick", "type": "omni.graph.action.OnTick"},
        {"name": "split", "type": "omni.graph.action.Sequence"},
        _counter("left"), _counter("right"),
        {"name": "gate", "type": "omni.graph.action.SyncGate"},
        _counter("passed"),
        connections=[("tick.outputs:tick", "split.inputs:execIn"), ("split.outputs:a", "left.inputs:execIn"),
                     ("split.outputs:b", "right.inputs:execIn"), ("left.outputs:execOut", "gate.inputs:execIn"),
                     ("right.outputs:execOut", "gate.inputs:execIn"), (sync_source, "gate.inputs:syncValue"),
                     ("gate.outputs:execOut", "passed.inputs:execIn")])


def test_sync_gate_fires_when_both_wired_signals_arrive_at_one_sync_value():
    # synced on the left count, which both arrivals of a tick see alike: the gate passes once a tick
    harness = GraphHarness(_sync_graph("left.outputs:count"))
    harness.run(5)
    assert harness.output("passed", "count") == 5
    assert harness.output("gate", "syncValue") == 5


def test_sync_gate_counts_per_sync_value_not_per_tick():
    # synced on the right count, which the right chain bumps between the two arrivals of a tick: tick n's
    # right arrival (value n) and tick n+1's left arrival (value n) make the pair. Tick 1's left arrival
    # (value 0) pairs with nothing (its right one brings 1), so 5 ticks pass 4 times.
    harness = GraphHarness(_sync_graph("right.outputs:count"))
    harness.run(1)
    assert harness.output("passed", "count") == 0
    harness.run(4)
    assert harness.output("passed", "count") == 4
    assert harness.output("gate", "syncValue") == 5


def test_rational_sync_gate_treats_reduced_equal_times_as_one():
    """Both arrivals of a tick: left at 1/2, right at 3/6 (the same time): the gate passes; then right at
    2/0 after left at 1/0, which do not reduce to one another: it does not."""
    graph = _sync_graph("left.outputs:count")
    graph["nodes"][4] = {"name": "gate", "type": "omni.graph.action.RationalTimeSyncGate"}
    graph["connections"] = [c for c in graph["connections"] if c["dst"] != "gate.inputs:syncValue"]
    harness = GraphHarness(graph)
    gate = harness.instance.database("gate")
    for numerator, denominator, fires in ((1, 2, False), (3, 6, True), (1, 0, False), (2, 0, False)):
        gate.inputs.rationalTimeNumerator, gate.inputs.rationalTimeDenominator = numerator, denominator
        harness.instance.compute_node("gate", ("execIn",))
        assert (gate.outputs.execOut != 0) == fires, (numerator, denominator)
        gate.outputs.execOut = 0


def test_for_each_target_visits_each_prim_then_finishes():
    harness = GraphHarness(_graph(
        {"name": "start", "type": "omni.graph.action.OnLoaded"},
        {"name": "loop", "type": "omni.graph.action.ForEachTarget", "inputs": {"targets": ["/World/a", "/World/b"]}},
        _counter("body"), _counter("done"),
        connections=[("start.outputs:execOut", "loop.inputs:execIn"), ("loop.outputs:loopBody", "body.inputs:execIn"),
                     ("loop.outputs:finished", "done.inputs:execIn")]))
    harness.run(1)
    assert (harness.output("body", "count"), harness.output("done", "count")) == (2, 1)
    assert harness.output("loop", "target") == ("/World/b",) and harness.output("loop", "arrayIndex") == 1
