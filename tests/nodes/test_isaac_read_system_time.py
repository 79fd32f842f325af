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


def test_system_time_at_a_reference_time_is_that_time():
    """Isaac 5's referenceTimeNumerator / referenceTimeDenominator ask for the system time at a timeline time;
    on the run's clock that is the time itself (3/4 s), and a zero denominator means now."""
    from graphflow.testing import NodeHarness

    node = NodeHarness("isaacsim.core.nodes.IsaacReadSystemTime",
                       {"referenceTimeNumerator": 3, "referenceTimeDenominator": 4})
    assert node.compute().outputs["systemTime"] == 0.75
    node.set_inputs(referenceTimeDenominator=0)
    assert node.tick().outputs["systemTime"] == pytest.approx(node.world.time_step)
