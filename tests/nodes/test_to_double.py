"""omni.graph.nodes.ToDouble: bools and numbers as doubles (key states into math)."""
import pytest

from graphflow.executor import GraphRuntimeError
from graphflow.testing import NodeHarness


@pytest.mark.parametrize("value, expected", [
    (True, 1.0), (False, 0.0), (3, 3.0), (-2.5, -2.5), ((True, False, 2), (1.0, 0.0, 2.0)),
    (((1, True), (0, False)), ((1.0, 1.0), (0.0, 0.0))),
])
def test_converts_keeping_the_shape(value, expected):
    converted = NodeHarness("omni.graph.nodes.ToDouble", inputs={"value": value}).compute().outputs["converted"]
    assert converted == expected
    assert all(type(x) is float for x in (converted if isinstance(converted, tuple) else [converted])
               if not isinstance(x, tuple))


def test_text_and_missing_values_are_errors():
    with pytest.raises(GraphRuntimeError, match="inputs:value must hold bools or numbers"):
        NodeHarness("omni.graph.nodes.ToDouble", inputs={"value": "A"}).compute()
    with pytest.raises(GraphRuntimeError, match="inputs:value has no value"):
        NodeHarness("omni.graph.nodes.ToDouble").compute()
