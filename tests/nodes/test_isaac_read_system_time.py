"""isaacsim.core.nodes.IsaacReadSystemTime: the run's clock (seconds since the run started), reproducible."""
import pytest

from graphflow.testing import GraphHarness

GRAPH = {
    "settings": {"timeStep": 0.01},
    "nodes": [
        {"name": "tick", "type": "omni.graph.action.OnTick"},
        {"name": "clock", "type": "omni.isaac.core_nodes.IsaacReadSystemTime"},
        {"name": "text", "type": "omni.graph.nodes.ToString"},
        {"name": "print", "type": "omni.graph.ui_nodes.PrintText"},
    ],
    "connections": [
        {"src": "tick.outputs:tick", "dst": "print.inputs:execIn"},
        {"src": "clock.outputs:systemTime", "dst": "text.inputs:value"},
        {"src": "text.outputs:converted", "dst": "print.inputs:text"},
    ],
}


def test_system_time_is_the_runs_clock_and_repeats():
    first = GraphHarness(GRAPH)
    first.run(ticks=50)
    assert first.output("clock", "systemTime") == pytest.approx(50 * first.world.time_step)
    second = GraphHarness(GRAPH)
    second.run(ticks=50)
    assert second.logs == first.logs
