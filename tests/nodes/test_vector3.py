"""omni.graph.nodes.MakeVector3 and BreakVector3."""
from graphflow.testing import GraphHarness, NodeHarness


def test_make_vector3_builds_a_double_tuple():
    r = NodeHarness("omni.graph.nodes.MakeVector3", inputs={"x": 1, "y": -2.5, "z": 0}).compute()
    assert r.outputs["tuple"] == (1.0, -2.5, 0.0)
    assert all(type(v) is float for v in r.outputs["tuple"])


def test_break_vector3_splits_components():
    r = NodeHarness("omni.graph.nodes.BreakVector3", inputs={"tuple": [0.1, 0.2, 0.3]}).compute()
    assert (r.outputs["x"], r.outputs["y"], r.outputs["z"]) == (0.1, 0.2, 0.3)


def test_make_scale_break_round_trip():
    g = GraphHarness({
        "nodes": [
            {"name": "tick", "type": "omni.graph.action.OnTick"},
            {"name": "make", "type": "omni.graph.nodes.MakeVector3", "inputs": {"x": 1.0, "y": 2.0, "z": 3.0}},
            {"name": "scale", "type": "omni.graph.nodes.Multiply", "inputs": {"b": 2.0}},
            {"name": "break", "type": "omni.graph.nodes.BreakVector3"},
            {"name": "fmt", "type": "graphflow.FormatText", "inputs": {"format": "z={value}"}},
            {"name": "print", "type": "omni.graph.ui_nodes.PrintText"},
        ],
        "connections": [
            {"src": "tick.outputs:tick", "dst": "print.inputs:execIn"},
            {"src": "make.outputs:tuple", "dst": "scale.inputs:a"},
            {"src": "scale.outputs:product", "dst": "break.inputs:tuple"},
            {"src": "break.outputs:z", "dst": "fmt.inputs:value"},
            {"src": "fmt.outputs:text", "dst": "print.inputs:text"},
        ],
    })
    g.run(ticks=1)
    assert g.logs == ["z=6.0"]
    assert g.output("scale", "product") == (2.0, 4.0, 6.0)


def test_two_vectors_and_prim_paths():
    from graphflow.testing import NodeHarness

    assert NodeHarness("omni.graph.nodes.MakeVector2", {"x": 1.5, "y": -2}).compute().outputs["tuple"] == (1.5, -2.0)
    split = NodeHarness("omni.graph.nodes.BreakVector2", {"tuple": [3.0, 4.0]}).compute().outputs
    assert (split["x"], split["y"]) == (3.0, 4.0)
    parents = NodeHarness("omni.graph.nodes.GetParentPrims", {"prims": ["/World/Cube", "/World"]}).compute()
    assert parents.outputs["parentPrims"] == ("/World", "/")
    assert NodeHarness("omni.graph.nodes.GetPrimPath", {"prim": ["/World/Cube"]}).compute().outputs["primPath"] == (
        "/World/Cube")
