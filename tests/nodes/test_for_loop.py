"""omni.graph.action.ForLoop: the whole loop runs inside one tick."""
import pytest

from graphflow.executor import GraphRuntimeError
from graphflow.testing import ExecState, GraphHarness, NodeHarness


def _loop_graph(loop_inputs, break_at=None):
    nodes = [
        {"name": "tick", "type": "omni.graph.action.OnTick"},
        {"name": "loop", "type": "omni.graph.action.ForLoop", "inputs": loop_inputs},
        {"name": "fmt", "type": "graphflow.FormatText", "inputs": {"format": "{value}"}},
        {"name": "body", "type": "omni.graph.ui_nodes.PrintText"},
        {"name": "done", "type": "omni.graph.ui_nodes.PrintText", "inputs": {"text": "finished"}},
    ]
    connections = [
        {"src": "tick.outputs:tick", "dst": "loop.inputs:execIn"},
        {"src": "loop.outputs:loopBody", "dst": "body.inputs:execIn"},
        {"src": "loop.outputs:value", "dst": "fmt.inputs:value"},
        {"src": "fmt.outputs:text", "dst": "body.inputs:text"},
        {"src": "loop.outputs:finished", "dst": "done.inputs:execIn"},
    ]
    if break_at is not None:
        nodes += [
            {"name": "cmp", "type": "omni.graph.nodes.Compare", "inputs": {"b": break_at, "operation": "=="}},
            {"name": "br", "type": "omni.graph.action.Branch"},
        ]
        connections += [
            {"src": "body.outputs:execOut", "dst": "br.inputs:execIn"},
            {"src": "loop.outputs:value", "dst": "cmp.inputs:a"},
            {"src": "cmp.outputs:result", "dst": "br.inputs:condition"},
            {"src": "br.outputs:execTrue", "dst": "loop.inputs:breakLoop"},
        ]
    return GraphHarness({"nodes": nodes, "connections": connections})


def test_loop_body_runs_for_each_value_then_finished_in_one_tick():
    g = _loop_graph({"start": 2, "stop": 5})
    g.run(ticks=1)
    assert g.logs == ["2", "3", "4", "finished"]
    g.run(ticks=1)
    assert g.logs == ["2", "3", "4", "finished"] * 2


def test_negative_step_counts_down_and_index_counts_iterations():
    h = NodeHarness("omni.graph.action.ForLoop", inputs={"start": 10, "stop": 4, "step": -3})
    r = h.compute("execIn")
    assert (r.exec_states["loopBody"], r.outputs["index"], r.outputs["value"]) == (ExecState.ENABLED_AND_PUSH, 0, 10)
    r = h.compute()
    assert (r.outputs["index"], r.outputs["value"]) == (1, 7)
    assert h.compute().fired == {"finished"}


def test_empty_range_fires_finished_only():
    g = _loop_graph({"start": 3, "stop": 3})
    g.run(ticks=1)
    assert g.logs == ["finished"]


def test_break_loop_ends_after_current_iteration_and_fires_finished():
    g = _loop_graph({"start": 0, "stop": 10}, break_at=2)
    g.run(ticks=1)
    assert g.logs == ["0", "1", "2", "finished"]
    g.run(ticks=1)  # the next pulse starts a fresh loop
    assert g.logs[4:] == ["0", "1", "2", "finished"]


def test_zero_step_arriving_at_run_time_is_an_error():
    h = NodeHarness("omni.graph.action.ForLoop", inputs={"stop": 3})
    with pytest.raises(GraphRuntimeError, match="step must not be 0"):
        h.compute("execIn", step=0)


def test_authored_zero_step_is_rejected_at_load():
    from graphflow.document import GraphError

    with pytest.raises(GraphError, match="inputs:step must not be 0"):
        NodeHarness("omni.graph.action.ForLoop", inputs={"step": 0})
