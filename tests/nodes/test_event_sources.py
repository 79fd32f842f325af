"""OnTick, OnPlaybackTick and OnImpulseEvent: the entry points of every action graph."""
import pytest

from graphflow.testing import ExecState, GraphHarness, NodeHarness


def _counted(source_type, source_out, inputs=None):
    return GraphHarness({
        "nodes": [
            {"name": "src", "type": source_type, "inputs": inputs or {}},
            {"name": "cnt", "type": "omni.graph.action.Counter"},
        ],
        "connections": [{"src": f"src.outputs:{source_out}", "dst": "cnt.inputs:execIn"}],
    })


def test_on_tick_fires_every_tick_with_clock_outputs():
    h = NodeHarness("omni.graph.action.OnTick", time_step=0.01)
    for frame in (1, 2, 3):
        r = h.tick()
        assert r.exec_states["tick"] == ExecState.ENABLED
        assert r.outputs["frame"] == frame
        assert r.outputs["time"] == pytest.approx(0.01 * frame)
        assert r.outputs["timeSinceStart"] == pytest.approx(0.01 * frame)
        assert r.outputs["absoluteSimTime"] == pytest.approx(0.01 * frame)
        assert r.outputs["deltaSeconds"] == pytest.approx(0.01)
        assert r.outputs["isPlaying"] is True


def test_on_tick_frame_period_skips_ticks_and_accumulates_delta():
    h = NodeHarness("omni.graph.action.OnTick", inputs={"framePeriod": 2}, time_step=0.1)
    fired = [bool(h.tick().fired) for _ in range(7)]
    assert fired == [True, False, False, True, False, False, True]
    assert h.outputs.deltaSeconds == pytest.approx(0.3)
    assert h.outputs.frame == 7


def test_on_tick_drives_downstream_once_per_tick():
    g = _counted("omni.graph.action.OnTick", "tick")
    g.run(ticks=5)
    assert g.output("cnt", "count") == 5


def test_on_tick_frame_period_restarts_after_reset():
    g = _counted("omni.graph.action.OnTick", "tick", {"framePeriod": 1})
    g.run(ticks=3)
    assert g.output("cnt", "count") == 2  # ticks 1 and 3
    g.reset()
    g.run(ticks=1)
    assert g.output("cnt", "count") == 1  # fires again on the first tick after reset


def test_on_playback_tick_reports_step_time_and_frame():
    h = NodeHarness("omni.graph.action.OnPlaybackTick", time_step=0.25)
    h.tick()
    r = h.tick()
    assert r.fired == {"tick"}
    assert r.outputs["deltaSeconds"] == pytest.approx(0.25)
    assert r.outputs["time"] == pytest.approx(0.5)
    assert r.outputs["frame"] == 2.0


def test_on_playback_tick_accepts_its_typeversion_2_as_in_isaac_files():
    g = GraphHarness({
        "nodes": [
            {"name": "src", "type": "omni.graph.action.OnPlaybackTick", "typeVersion": 2},
            {"name": "cnt", "type": "omni.graph.action.Counter"},
        ],
        "connections": [{"src": "src.outputs:tick", "dst": "cnt.inputs:execIn"}],
    })
    g.run(ticks=4)
    assert g.output("cnt", "count") == 4


def test_on_impulse_event_fires_once_per_impulse_then_clears_it():
    g = _counted("omni.graph.action.OnImpulseEvent", "execOut")
    g.run(ticks=3)
    assert g.output("cnt", "count") == 0
    g.instance.set_state("src", "enableImpulse", True)
    g.run(ticks=3)
    assert g.output("cnt", "count") == 1
    assert g.state("src").enableImpulse is False
    g.instance.set_state("src", "enableImpulse", True)
    g.run(ticks=1)
    assert g.output("cnt", "count") == 2


def test_on_impulse_event_node_level():
    h = NodeHarness("omni.graph.action.OnImpulseEvent")
    assert h.tick().fired == set()
    h.state.enableImpulse = True
    assert h.tick().fired == {"execOut"}
    assert h.tick().fired == set()
