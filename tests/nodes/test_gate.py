"""omni.graph.action.Gate."""
from graphflow.testing import NodeHarness


def test_open_gate_passes_enter():
    h = NodeHarness("omni.graph.action.Gate")
    assert h.compute("enter").fired == {"exit"}
    assert h.compute("enter").fired == {"exit"}


def test_toggle_closes_and_reopens_without_firing_exit():
    h = NodeHarness("omni.graph.action.Gate")
    assert h.compute("toggle").fired == set()
    assert h.compute("enter").fired == set()
    assert h.compute("toggle").fired == set()
    assert h.compute("enter").fired == {"exit"}


def test_start_closed_and_reset_returns_to_closed():
    h = NodeHarness("omni.graph.action.Gate", inputs={"startClosed": True})
    assert h.compute("enter").fired == set()
    h.compute("toggle")
    assert h.compute("enter").fired == {"exit"}
    h.reset()
    assert h.compute("enter").fired == set()
    assert h.state.isOpen is False


def test_toggle_and_enter_together_apply_toggle_first():
    h = NodeHarness("omni.graph.action.Gate", inputs={"startClosed": True})
    assert h.compute("toggle", "enter").fired == {"exit"}
