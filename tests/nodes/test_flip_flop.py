"""omni.graph.action.FlipFlop."""
from graphflow.testing import GraphHarness, NodeHarness


def test_alternates_a_and_b_starting_with_a():
    h = NodeHarness("omni.graph.action.FlipFlop")
    results = [h.compute("execIn") for _ in range(4)]
    assert [r.fired for r in results] == [{"a"}, {"b"}, {"a"}, {"b"}]
    assert [r.outputs["isA"] for r in results] == [True, False, True, False]


def test_reset_starts_again_with_a():
    h = NodeHarness("omni.graph.action.FlipFlop")
    h.compute("execIn")
    h.reset()
    assert h.compute("execIn").fired == {"a"}


def test_flip_flop_splits_ticks_between_two_counters():
    g = GraphHarness({
        "nodes": [
            {"name": "tick", "type": "omni.graph.action.OnTick"},
            {"name": "ff", "type": "omni.graph.action.FlipFlop"},
            {"name": "ca", "type": "omni.graph.action.Counter"},
            {"name": "cb", "type": "omni.graph.action.Counter"},
        ],
        "connections": [
            {"src": "tick.outputs:tick", "dst": "ff.inputs:execIn"},
            {"src": "ff.outputs:a", "dst": "ca.inputs:execIn"},
            {"src": "ff.outputs:b", "dst": "cb.inputs:execIn"},
        ],
    })
    g.run(ticks=5)
    assert (g.output("ca", "count"), g.output("cb", "count")) == (3, 2)
