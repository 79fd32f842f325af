"""omni.graph.nodes.Constant*: inputs:value passed to outputs:value."""
import pytest

from graphflow.document import GraphError
from graphflow.testing import GraphHarness, NodeHarness

CASES = [
    ("omni.graph.nodes.ConstantBool", True, True),
    ("omni.graph.nodes.ConstantInt", -7, -7),
    ("omni.graph.nodes.ConstantDouble", 2, 2.0),
    ("omni.graph.nodes.ConstantFloat", -0.05, -0.05),
    ("omni.graph.nodes.ConstantToken", "Close", "Close"),
    ("omni.graph.nodes.ConstantString", "hello world", "hello world"),
    ("omni.graph.nodes.ConstantDouble3", [1, 2, 3], (1.0, 2.0, 3.0)),
]


@pytest.mark.parametrize("type_id, authored, expected", CASES)
def test_constant_outputs_its_authored_value(type_id, authored, expected):
    r = NodeHarness(type_id, inputs={"value": authored}).compute()
    assert r.outputs["value"] == expected
    assert type(r.outputs["value"]) is type(expected)


@pytest.mark.parametrize("type_id, zero", [
    ("omni.graph.nodes.ConstantBool", False), ("omni.graph.nodes.ConstantInt", 0),
    ("omni.graph.nodes.ConstantFloat", 0.0), ("omni.graph.nodes.ConstantToken", ""),
    ("omni.graph.nodes.ConstantDouble3", (0.0, 0.0, 0.0)),
])
def test_unset_constant_is_the_type_zero(type_id, zero):
    assert NodeHarness(type_id).compute().outputs["value"] == zero


def test_constant_rejects_a_value_of_the_wrong_type_at_load():
    with pytest.raises(GraphError, match="inputs:value"):
        NodeHarness("omni.graph.nodes.ConstantDouble3", inputs={"value": [1, 2]})


def test_constant_float_feeds_multiply_like_the_isaac_gantry_graph():
    g = GraphHarness({
        "nodes": [
            {"name": "tick", "type": "omni.graph.action.OnTick"},
            {"name": "k", "type": "omni.graph.nodes.ConstantFloat", "inputs": {"value": -0.05}},
            {"name": "mul", "type": "omni.graph.nodes.Multiply", "inputs": {"a": 4.0}},
            {"name": "fmt", "type": "graphflow.FormatText", "inputs": {"format": "{value:.2f}"}},
            {"name": "print", "type": "omni.graph.ui_nodes.PrintText"},
        ],
        "connections": [
            {"src": "tick.outputs:tick", "dst": "print.inputs:execIn"},
            {"src": "k.outputs:value", "dst": "mul.inputs:b"},
            {"src": "mul.outputs:product", "dst": "fmt.inputs:value"},
            {"src": "fmt.outputs:text", "dst": "print.inputs:text"},
        ],
    })
    g.run(ticks=1)
    assert g.logs == ["-0.20"]


def test_constants_and_targets_size_pass_their_values_on():
    assert __import__("graphflow.testing").testing.NodeHarness("omni.graph.nodes.GetTargetsSize", {"targets": ["/a", "/b", "/c"]}).compute().outputs["size"] == 3
    for type_id, value in (("ConstantHalf", 0.5), ("ConstantInt2", [1, 2]), ("ConstantPoint3f", [1.0, 2.0, 3.0]),
                           ("ConstantDouble4", [1.0, 2.0, 3.0, 4.0]), ("ConstantFloat4", [1.0, 2.0, 3.0, 4.0]),
                           ("ConstantQuatf", [0.0, 0.0, 0.0, 1.0]), ("ConstantVector3f", [0.0, 1.0, 0.0]),
                           ("ConstantColor3d", [0.1, 0.2, 0.3]), ("ConstantColor3f", [0.5, 0.5, 0.5]),
                           ("ConstantColor4d", [0.1, 0.2, 0.3, 1.0]), ("ConstantColor4f", [0.0, 0.0, 0.0, 1.0]),
                           ("ConstantHalf2", [0.5, 1.5]), ("ConstantHalf3", [0.5, 1.5, 2.5]), ("ConstantInt3", [1, 2, 3]),
                           ("ConstantInt4", [1, 2, 3, 4]), ("ConstantNormal3d", [0.0, 0.0, 1.0]),
                           ("ConstantNormal3f", [1.0, 0.0, 0.0]), ("ConstantQuath", [0.0, 0.0, 0.0, 1.0]),
                           ("ConstantTarget", ["/World/a", "/World/b"])):
        out = __import__("graphflow.testing").testing.NodeHarness(f"omni.graph.nodes.{type_id}", {"value": value}).compute().outputs["value"]
        assert out == (tuple(value) if isinstance(value, list) else value)
