"""omni.graph.action.ForEach."""
from graphflow.testing import ExecState, GraphHarness, NodeHarness


def test_loops_over_elements_in_order_within_one_tick():
    g = GraphHarness({
        "nodes": [
            {"name": "tick", "type": "omni.graph.action.OnTick"},
            {"name": "each", "type": "omni.graph.action.ForEach", "inputs": {"arrayIn": ["x", "y", "z"]}},
            {"name": "fmt", "type": "graphflow.FormatText", "inputs": {"format": "{}"}},
            {"name": "idx", "type": "graphflow.FormatText", "inputs": {"format": "#{value}"}},
            {"name": "pi", "type": "omni.graph.ui_nodes.PrintText"},
            {"name": "pe", "type": "omni.graph.ui_nodes.PrintText"},
            {"name": "done", "type": "omni.graph.ui_nodes.PrintText", "inputs": {"text": "done"}},
        ],
        "connections": [
            {"src": "tick.outputs:tick", "dst": "each.inputs:execIn"},
            {"src": "each.outputs:loopBody", "dst": "pi.inputs:execIn"},
            {"src": "pi.outputs:execOut", "dst": "pe.inputs:execIn"},
            {"src": "each.outputs:arrayIndex", "dst": "idx.inputs:value"},
            {"src": "idx.outputs:text", "dst": "pi.inputs:text"},
            {"src": "each.outputs:element", "dst": "fmt.inputs:value"},
            {"src": "fmt.outputs:text", "dst": "pe.inputs:text"},
            {"src": "each.outputs:finished", "dst": "done.inputs:execIn"},
        ],
    })
    g.run(ticks=1)
    assert g.logs == ["#0", "x", "#1", "y", "#2", "z", "done"]


def test_node_level_element_and_index_outputs():
    h = NodeHarness("omni.graph.action.ForEach", inputs={"arrayIn": [[1.0, 2.0, 3.0], [4.0, 5.0, 6.0]]})
    r = h.compute("execIn")
    assert r.exec_states["loopBody"] == ExecState.ENABLED_AND_PUSH
    assert (r.outputs["element"], r.outputs["arrayIndex"]) == ((1.0, 2.0, 3.0), 0)
    r = h.compute()
    assert (r.outputs["element"], r.outputs["arrayIndex"]) == ((4.0, 5.0, 6.0), 1)
    assert h.compute().fired == {"finished"}
    assert h.compute().fired == set()


def test_empty_array_fires_finished_at_once():
    h = NodeHarness("omni.graph.action.ForEach", inputs={"arrayIn": []})
    assert h.compute("execIn").fired == {"finished"}


def test_array_is_snapshotted_when_the_loop_starts():
    h = NodeHarness("omni.graph.action.ForEach", inputs={"arrayIn": [1, 2]})
    h.compute("execIn")
    h.set_inputs(arrayIn=[7, 8, 9])  # a change mid-loop does not affect this loop
    assert h.compute().outputs["element"] == 2
    assert h.compute().fired == {"finished"}
