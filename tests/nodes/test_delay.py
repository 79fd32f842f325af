"""omni.graph.action.Delay: latent, counts simulated time, ignores pulses while running."""
import pytest

from graphflow.testing import ExecState, GraphHarness, NodeHarness


def _graph(duration, extra_nodes=(), extra_connections=()):
    return GraphHarness({
        "settings": {"timeStep": 0.1},
        "nodes": [
            {"name": "tick", "type": "omni.graph.action.OnTick"},
            {"name": "once", "type": "omni.graph.action.Once"},
            {"name": "delay", "type": "omni.graph.action.Delay", "inputs": {"duration": duration}},
            {"name": "done", "type": "omni.graph.ui_nodes.PrintText", "inputs": {"text": "done"}},
            *extra_nodes,
        ],
        "connections": [
            {"src": "tick.outputs:tick", "dst": "once.inputs:execIn"},
            {"src": "once.outputs:once", "dst": "delay.inputs:execIn"},
            {"src": "delay.outputs:finished", "dst": "done.inputs:execIn"},
            *extra_connections,
        ],
    })


def test_node_goes_latent_then_finishes_after_duration():
    h = NodeHarness("omni.graph.action.Delay", inputs={"duration": 0.3}, time_step=0.1)
    r = h.compute("execIn")
    assert r.exec_states["finished"] == ExecState.LATENT_PUSH
    assert h.is_latent
    assert h.tick().fired == set()
    assert h.tick().fired == set()
    r = h.tick()
    assert r.exec_states["finished"] == ExecState.LATENT_FINISH
    assert not h.is_latent
    assert h.state.elapsed == pytest.approx(0.3)


def test_pulses_while_latent_are_ignored():
    h = NodeHarness("omni.graph.action.Delay", inputs={"duration": 0.2}, time_step=0.1)
    h.compute("execIn")
    h.tick()
    assert h.tick("execIn").fired == set()  # locked: no restart, no output
    assert h.is_latent
    assert h.tick().exec_states["finished"] == ExecState.LATENT_FINISH


def test_zero_duration_fires_at_once():
    h = NodeHarness("omni.graph.action.Delay", inputs={"duration": 0.0})
    assert h.compute("execIn").exec_states["finished"] == ExecState.ENABLED
    assert not h.is_latent


def test_finished_fires_downstream_duration_later_in_a_graph():
    g = _graph(0.5)
    g.run(ticks=5)
    assert g.logs == []  # pulsed on tick 1; 0.4 s elapsed by tick 5
    g.run(ticks=1)
    assert g.logs == ["done"]  # tick 6: 0.5 s after the pulse
    g.run(ticks=5)
    assert g.logs == ["done"]


def test_delay_restarts_after_finishing_and_graph_reset_clears_latent_state():
    # OnTick pulses the delay every tick; it is locked while running, so it fires every 3rd tick
    g = GraphHarness({
        "settings": {"timeStep": 0.1},
        "nodes": [
            {"name": "tick", "type": "omni.graph.action.OnTick"},
            {"name": "delay", "type": "omni.graph.action.Delay", "inputs": {"duration": 0.2}},
            {"name": "cnt", "type": "omni.graph.action.Counter"},
        ],
        "connections": [
            {"src": "tick.outputs:tick", "dst": "delay.inputs:execIn"},
            {"src": "delay.outputs:finished", "dst": "cnt.inputs:execIn"},
        ],
    })
    g.run(ticks=7)  # starts on 1, finishes on 3; restarts on 4, finishes on 6; restarts on 7
    assert g.output("cnt", "count") == 2
    g.reset()
    assert g.instance.database("delay").is_latent is False
    g.run(ticks=3)
    assert g.output("cnt", "count") == 1
