"""omni.graph.action.Sequence (a then b) and Multisequence (output0..output7 in order)."""
from graphflow.testing import ExecState, GraphHarness, NodeHarness


def _printer(name, text):
    return {"name": name, "type": "omni.graph.ui_nodes.PrintText", "inputs": {"text": text}}


def test_sequence_pushes_a_then_enables_b_on_reentry():
    h = NodeHarness("omni.graph.action.Sequence")
    first = h.compute("execIn")
    assert first.exec_states == {"a": ExecState.ENABLED_AND_PUSH, "b": ExecState.DISABLED}
    second = h.compute()  # re-entry: no exec input enabled
    assert second.exec_states == {"a": ExecState.DISABLED, "b": ExecState.ENABLED}
    assert h.compute().fired == set()  # nothing pending any more


def test_sequence_runs_all_of_a_before_b():
    g = GraphHarness({
        "nodes": [
            {"name": "tick", "type": "omni.graph.action.OnTick"},
            {"name": "seq", "type": "omni.graph.action.Sequence"},
            _printer("a1", "a1"), _printer("a2", "a2"), _printer("b1", "b1"),
        ],
        "connections": [
            {"src": "tick.outputs:tick", "dst": "seq.inputs:execIn"},
            {"src": "seq.outputs:a", "dst": "a1.inputs:execIn"},
            {"src": "a1.outputs:execOut", "dst": "a2.inputs:execIn"},
            {"src": "seq.outputs:b", "dst": "b1.inputs:execIn"},
        ],
    })
    g.run(ticks=2)
    assert g.logs == ["a1", "a2", "b1", "a1", "a2", "b1"]
    assert g.compute_counts["seq"] == 4  # pulse + re-entry per tick


def test_multisequence_fires_outputs_in_order_each_after_the_previous_downstream():
    g = GraphHarness({
        "nodes": [
            {"name": "tick", "type": "omni.graph.action.OnTick"},
            {"name": "seq", "type": "omni.graph.action.Multisequence"},
            _printer("p0", "zero"), _printer("p0b", "zero-after"), _printer("p1", "one"), _printer("p3", "three"),
        ],
        "connections": [
            {"src": "tick.outputs:tick", "dst": "seq.inputs:execIn"},
            {"src": "seq.outputs:output0", "dst": "p0.inputs:execIn"},
            {"src": "p0.outputs:execOut", "dst": "p0b.inputs:execIn"},
            {"src": "seq.outputs:output1", "dst": "p1.inputs:execIn"},
            {"src": "seq.outputs:output3", "dst": "p3.inputs:execIn"},
        ],
    })
    g.run(ticks=2)
    assert g.logs == ["zero", "zero-after", "one", "three"] * 2


def test_multisequence_node_level_walks_all_eight_outputs():
    h = NodeHarness("omni.graph.action.Multisequence")
    states = [h.compute("execIn").exec_states] + [h.compute().exec_states for _ in range(7)]
    for i, exec_states in enumerate(states):
        expected = ExecState.ENABLED if i == 7 else ExecState.ENABLED_AND_PUSH
        assert exec_states[f"output{i}"] == expected
        assert [n for n, s in exec_states.items() if s != ExecState.DISABLED] == [f"output{i}"]
    assert h.compute().fired == set()
