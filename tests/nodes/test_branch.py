"""omni.graph.action.Branch."""
from graphflow.testing import ExecState, GraphHarness, NodeHarness


def test_branch_routes_by_condition():
    h = NodeHarness("omni.graph.action.Branch")
    assert h.compute("execIn", condition=True).exec_states == {
        "execTrue": ExecState.ENABLED, "execFalse": ExecState.DISABLED}
    assert h.compute("execIn", condition=False).fired == {"execFalse"}


def test_branch_condition_defaults_to_false():
    assert NodeHarness("omni.graph.action.Branch").compute("execIn").fired == {"execFalse"}


def test_branch_in_a_graph_follows_a_pulled_condition():
    # condition = (counter's count > 2): the first two ticks go false, later ones true
    g = GraphHarness({
        "nodes": [
            {"name": "tick", "type": "omni.graph.action.OnTick"},
            {"name": "cnt", "type": "omni.graph.action.Counter"},
            {"name": "cmp", "type": "omni.graph.nodes.Compare", "inputs": {"b": 2, "operation": ">"}},
            {"name": "br", "type": "omni.graph.action.Branch"},
            {"name": "yes", "type": "omni.graph.action.Counter"},
            {"name": "no", "type": "omni.graph.action.Counter"},
        ],
        "connections": [
            {"src": "tick.outputs:tick", "dst": "cnt.inputs:execIn"},
            {"src": "cnt.outputs:execOut", "dst": "br.inputs:execIn"},
            {"src": "cnt.outputs:count", "dst": "cmp.inputs:a"},
            {"src": "cmp.outputs:result", "dst": "br.inputs:condition"},
            {"src": "br.outputs:execTrue", "dst": "yes.inputs:execIn"},
            {"src": "br.outputs:execFalse", "dst": "no.inputs:execIn"},
        ],
    })
    g.run(ticks=5)
    assert g.output("no", "count") == 2
    assert g.output("yes", "count") == 3
