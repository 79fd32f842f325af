"""omni.graph.nodes.Compare."""
import pytest

from graphflow.document import GraphError
from graphflow.executor import GraphRuntimeError
from graphflow.testing import NodeHarness


def _compare(a, b, operation):
    return NodeHarness("omni.graph.nodes.Compare", inputs={"a": a, "b": b, "operation": operation}).compute().outputs["result"]


@pytest.mark.parametrize("operation, expected", [
    (">", [False, False, True]), ("<", [True, False, False]), (">=", [False, True, True]),
    ("<=", [True, True, False]), ("==", [False, True, False]), ("!=", [True, False, True]),
])
def test_every_operation_on_scalars(operation, expected):
    assert [_compare(a, 2, operation) for a in (1, 2, 3.5)] == expected


def test_tuples_and_arrays_compare_elementwise_with_broadcast():
    assert _compare([1.0, 2.0, 3.0], 2.0, ">=") == (False, True, True)
    assert _compare([1, 2], [1, 3], "==") == (True, False)


def test_tokens_compare_as_text():
    assert _compare("Close", "Close", "==") is True
    assert _compare("apple", "banana", "<") is True


def test_unknown_operation_is_rejected_at_load():
    with pytest.raises(GraphError, match="inputs:operation"):
        NodeHarness("omni.graph.nodes.Compare", inputs={"a": 1, "b": 2, "operation": "=>"})


def test_mixed_text_and_number_is_an_error():
    with pytest.raises(GraphRuntimeError, match="inputs:a must hold numbers"):
        _compare("1", 1, "==")
