"""Add, Subtract, Multiply, Divide, Minimum, Maximum, Clamp: elementwise with broadcasting."""
import numpy as np
import pytest

from graphflow.executor import GraphRuntimeError
from graphflow.testing import GraphHarness, NodeHarness

BINARY = [
    ("omni.graph.nodes.Add", "sum", 7, 2, 9),
    ("omni.graph.nodes.Subtract", "difference", 7, 2, 5),
    ("omni.graph.nodes.Multiply", "product", 7, 2, 14),
    ("omni.graph.nodes.Divide", "result", 7, 2, 3.5),
    ("omni.graph.nodes.Minimum", "minimum", 7, 2, 2),
    ("omni.graph.nodes.Maximum", "maximum", 7, 2, 7),
]


def _binary(type_id, output, a, b):
    return NodeHarness(type_id, inputs={"a": a, "b": b}).compute().outputs[output]


@pytest.mark.parametrize("type_id, output, a, b, expected", BINARY)
def test_scalars(type_id, output, a, b, expected):
    result = _binary(type_id, output, a, b)
    assert result == expected
    assert type(result) is type(expected)  # ints stay ints except for Divide


def test_tuples_combine_elementwise():
    assert _binary("omni.graph.nodes.Add", "sum", [1.0, 2.0, 3.0], [10.0, 20.0, 30.0]) == (11.0, 22.0, 33.0)
    assert _binary("omni.graph.nodes.Subtract", "difference", [1, 2, 3], [1, 1, 1]) == (0, 1, 2)
    assert _binary("omni.graph.nodes.Minimum", "minimum", [1, 5, 3], [4, 2, 6]) == (1, 2, 3)
    assert _binary("omni.graph.nodes.Maximum", "maximum", [1, 5, 3], [4, 2, 6]) == (4, 5, 6)


def test_scalar_broadcasts_over_tuple_on_either_side():
    assert _binary("omni.graph.nodes.Multiply", "product", [1.0, -2.0, 0.5], 2.0) == (2.0, -4.0, 1.0)
    assert _binary("omni.graph.nodes.Subtract", "difference", 10, [1, 2, 3]) == (9, 8, 7)
    assert _binary("omni.graph.nodes.Divide", "result", [2.0, 4.0], 2) == (1.0, 2.0)


def test_tuple_broadcasts_over_array_of_tuples():
    points = [[0.0, 0.0, 0.0], [1.0, 1.0, 1.0]]
    assert _binary("omni.graph.nodes.Add", "sum", points, [0.5, 0.0, -1.0]) == (
        (0.5, 0.0, -1.0), (1.5, 1.0, 0.0))


def test_numpy_values_become_plain_python():
    h = NodeHarness("omni.graph.nodes.Add")
    h.database.inputs.a = np.array([1.0, 2.0])
    h.database.inputs.b = np.float64(0.5)
    result = h.compute().outputs["sum"]
    assert result == (1.5, 2.5)
    assert type(result) is tuple and type(result[0]) is float


def test_length_mismatch_is_an_error_naming_the_inputs():
    with pytest.raises(GraphRuntimeError, match=r"inputs:a, inputs:b: lengths 3 and 2 differ"):
        _binary("omni.graph.nodes.Add", "sum", [1, 2, 3], [1, 2])


def test_unset_operand_is_an_error():
    with pytest.raises(GraphRuntimeError, match="inputs:b has no value"):
        NodeHarness("omni.graph.nodes.Multiply", inputs={"a": 2}).compute()


def test_non_numbers_are_rejected():
    with pytest.raises(GraphRuntimeError, match="inputs:a must hold numbers"):
        _binary("omni.graph.nodes.Add", "sum", "abc", 1)
    with pytest.raises(GraphRuntimeError, match="inputs:b must hold numbers"):
        _binary("omni.graph.nodes.Add", "sum", 1, True)


@pytest.mark.parametrize("b", [0, 0.0, [1.0, 0.0]])
def test_division_by_zero_is_an_error_naming_the_node(b):
    with pytest.raises(GraphRuntimeError, match=r"node 'node': division by zero"):
        _binary("omni.graph.nodes.Divide", "result", [3.0, 3.0], b)


def test_clamp_scalar_tuple_and_per_element_bounds():
    def clamp(value, lower, upper):
        return NodeHarness("omni.graph.nodes.Clamp",
                           inputs={"input": value, "lower": lower, "upper": upper}).compute().outputs["result"]
    assert clamp(5, 0, 3) == 3
    assert clamp(-1.5, -1.0, 1.0) == -1.0
    assert clamp(0.25, 0.0, 1.0) == 0.25
    assert clamp([-2.0, 0.5, 9.0], 0.0, 1.0) == (0.0, 0.5, 1.0)
    assert clamp([5, 5, 5], [0, 6, 0], [1, 9, 9]) == (1, 6, 5)


def test_clamp_lower_above_upper_is_an_error():
    with pytest.raises(GraphRuntimeError, match=r"inputs:lower \(2\) is greater than inputs:upper \(1\)"):
        NodeHarness("omni.graph.nodes.Clamp", inputs={"input": 0, "lower": 2, "upper": 1}).compute()


def test_gantry_style_chain_clamps_an_accumulated_position():
    # position += 0.3 per tick, limited by Minimum/Maximum to [-1, 1] as in the Isaac gantry graph
    g = GraphHarness({
        "variables": [{"name": "x", "type": "double", "default": 0.0}],
        "nodes": [
            {"name": "tick", "type": "omni.graph.action.OnTick"},
            {"name": "read", "type": "omni.graph.core.ReadVariable", "inputs": {"variableName": "x"}},
            {"name": "add", "type": "omni.graph.nodes.Add", "inputs": {"b": 0.3}},
            {"name": "min", "type": "omni.graph.nodes.Minimum", "inputs": {"b": 1.0}},
            {"name": "max", "type": "omni.graph.nodes.Maximum", "inputs": {"b": -1.0}},
            {"name": "write", "type": "omni.graph.core.WriteVariable", "inputs": {"variableName": "x"}},
        ],
        "connections": [
            {"src": "tick.outputs:tick", "dst": "write.inputs:execIn"},
            {"src": "read.outputs:value", "dst": "add.inputs:a"},
            {"src": "add.outputs:sum", "dst": "min.inputs:a"},
            {"src": "min.outputs:minimum", "dst": "max.inputs:a"},
            {"src": "max.outputs:maximum", "dst": "write.inputs:value"},
        ],
    })
    g.run(ticks=3)
    assert g.instance.variables["x"] == pytest.approx(0.9)
    g.run(ticks=2)
    assert g.instance.variables["x"] == 1.0
