"""omni.graph.action.Once."""
from graphflow.testing import NodeHarness


def test_first_pulse_fires_once_then_after():
    h = NodeHarness("omni.graph.action.Once")
    assert h.compute("execIn").fired == {"once"}
    assert h.compute("execIn").fired == {"after"}
    assert h.compute("execIn").fired == {"after"}


def test_reset_pulse_rearms_without_firing():
    h = NodeHarness("omni.graph.action.Once")
    h.compute("execIn")
    assert h.compute("reset").fired == set()
    assert h.compute("execIn").fired == {"once"}
    assert h.compute("execIn").fired == {"after"}


def test_graph_reset_rearms():
    h = NodeHarness("omni.graph.action.Once")
    h.compute("execIn")
    h.reset()
    assert h.state.done is False
    assert h.compute("execIn").fired == {"once"}
