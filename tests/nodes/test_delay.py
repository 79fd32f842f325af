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


def test_timer_runs_from_start_to_end_value_over_its_duration_in_simulated_time():
    """0.5 s at 60 Hz: played on tick 1, the value moves (end - start) / 30 a tick from tick 2 and 'finished'
    fires on tick 31, the 30th step, with the end value."""
    from graphflow.testing import GraphHarness

    harness = GraphHarness({"nodes": [
        {"name": "start", "type": "omni.graph.action.OnLoaded"},
        {"name": "timer", "type": "omni.graph.nodes.Timer", "inputs": {"duration": 0.5, "startValue": 2.0,
                                                                        "endValue": 5.0}},
        {"name": "updates", "type": "omni.graph.action.Counter"},
        {"name": "done", "type": "omni.graph.action.Counter"}],
        "connections": [{"src": "start.outputs:execOut", "dst": "timer.inputs:play"},
                        {"src": "timer.outputs:updated", "dst": "updates.inputs:execIn"},
                        {"src": "timer.outputs:finished", "dst": "done.inputs:execIn"}]})
    values = []
    for _ in range(32):
        harness.run(1)
        values.append(harness.output("timer", "value"))
    assert values[0] == 2.0 and values[1] == pytest.approx(2.1) and values[15] == pytest.approx(3.5)
    assert values[30] == pytest.approx(5.0) and values[31] == pytest.approx(5.0)
    assert harness.output("done", "count") == 1
    assert harness.output("updates", "count") == 31      # the start, then one a tick for 30 ticks
