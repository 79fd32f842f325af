"""omni.graph.action.OnClosing: fires once, after the run's last tick, never on a tick."""
from graphflow.testing import GraphHarness

GRAPH = {
    "nodes": [
        {"name": "tick", "type": "omni.graph.action.OnTick"},
        {"name": "count", "type": "omni.graph.action.Counter"},
        {"name": "closing", "type": "omni.graph.action.OnClosing"},
        {"name": "text", "type": "omni.graph.nodes.ToString"},
        {"name": "print", "type": "omni.graph.ui_nodes.PrintText"},
    ],
    "connections": [
        {"src": "tick.outputs:tick", "dst": "count.inputs:execIn"},
        {"src": "closing.outputs:execOut", "dst": "print.inputs:execIn"},
        {"src": "count.outputs:count", "dst": "text.inputs:value"},
        {"src": "text.outputs:converted", "dst": "print.inputs:text"},
    ],
}


def test_on_closing_fires_once_after_the_last_tick():
    g = GraphHarness(GRAPH)
    g.run(ticks=5)
    assert g.logs == ["5"]                       # printed once, with the count the fifth tick left
    assert g.compute_counts["closing"] == 1
    assert g.compute_counts["count"] == 5      # the closing pass is no tick


def test_on_closing_fires_after_a_stop_request():
    graph = {**GRAPH, "nodes": GRAPH["nodes"] + [{"name": "stop", "type": "graphflow.StopRun"}],
             "connections": GRAPH["connections"] + [{"src": "count.outputs:execOut", "dst": "stop.inputs:execIn"}]}
    g = GraphHarness(graph)
    g.run(ticks=100)
    assert g.logs == ["1"]
