"""omni.graph.action.Counter."""
from graphflow.testing import ExecState, GraphHarness, NodeHarness


def test_counts_pulses_and_fires_exec_out():
    h = NodeHarness("omni.graph.action.Counter")
    for expected in (1, 2, 3):
        r = h.compute("execIn")
        assert r.outputs["count"] == expected
        assert r.exec_states["execOut"] == ExecState.ENABLED
    assert h.state.count == 3


def test_reset_pulse_zeroes_without_firing():
    h = NodeHarness("omni.graph.action.Counter")
    h.compute("execIn")
    h.compute("execIn")
    r = h.compute("reset")
    assert r.outputs["count"] == 0
    assert r.fired == set()
    assert h.compute("execIn").outputs["count"] == 1


def test_reset_and_exec_in_together_count_from_zero():
    h = NodeHarness("omni.graph.action.Counter")
    h.compute("execIn")
    h.compute("execIn")
    assert h.compute("reset", "execIn").outputs["count"] == 1


def test_graph_reset_restores_zero_count():
    g = GraphHarness({
        "nodes": [{"name": "tick", "type": "omni.graph.action.OnTick"},
                  {"name": "cnt", "type": "omni.graph.action.Counter"}],
        "connections": [{"src": "tick.outputs:tick", "dst": "cnt.inputs:execIn"}],
    })
    g.run(ticks=4)
    assert g.output("cnt", "count") == 4
    g.reset()
    assert g.state("cnt").count == 0
    g.run(ticks=2)
    assert g.output("cnt", "count") == 2
