"""omni.graph.nodes integer, bool and angle conversions and the string tests, on the reference's own rules.

Kit's reference: floats truncate towards zero; a negative value converted to an
unsigned type is 2^bits minus its magnitude (ToUint(-5) = 2^32 - 5).
"""
import math

import pytest

from graphflow.executor import GraphRuntimeError
from graphflow.testing import NodeHarness


def converted(type_id, value):
    return NodeHarness(type_id, inputs={"value": value}).compute().outputs["converted"]


@pytest.mark.parametrize("type_id, value, expected", [
    ("omni.graph.nodes.ToInt", -2.7, -2), ("omni.graph.nodes.ToInt", 2.7, 2), ("omni.graph.nodes.ToInt", True, 1),
    ("omni.graph.nodes.ToInt", (1.9, -1.9, False), (1, -1, 0)),
    ("omni.graph.nodes.ToInt", 2**31, -2**31),
    ("omni.graph.nodes.ToInt64", -7.99, -7), ("omni.graph.nodes.ToInt64", 2**40 + 0.5, 2**40),
    ("omni.graph.nodes.ToUint", -5, 2**32 - 5), ("omni.graph.nodes.ToUint", 3.99, 3),
    ("omni.graph.nodes.ToUint64", -1, 2**64 - 1), ("omni.graph.nodes.ToUchar", -1, 255),
    ("omni.graph.nodes.ToUchar", 256, 0), ("omni.graph.nodes.ToUchar", (65.2, 300), (65, 44)),
])
def test_integer_conversions_truncate_and_wrap_as_the_reference_says(type_id, value, expected):
    result = converted(type_id, value)
    assert result == expected
    assert all(type(x) is int for x in (result if isinstance(result, tuple) else (result,)))


@pytest.mark.parametrize("value, expected", [(0, False), (-0.0, False), (0.001, True), (-3, True), (True, True),
                                             ((0, 2, 0.0), (False, True, False))])
def test_to_bool_is_true_for_non_zero(value, expected):
    assert converted("omni.graph.nodes.ToBool", value) == expected


def test_conversions_refuse_what_has_no_integer_value():
    with pytest.raises(GraphRuntimeError, match="no integer value"):
        converted("omni.graph.nodes.ToInt", math.inf)
    with pytest.raises(GraphRuntimeError, match="must hold bools or numbers"):
        converted("omni.graph.nodes.ToUint", "7")
    with pytest.raises(GraphRuntimeError, match="array of scalars"):
        converted("omni.graph.nodes.ToUint", ((1, 2), (3, 4)))


def test_degrees_and_radians_round_trip():
    degrees = NodeHarness("omni.graph.nodes.ToDeg", inputs={"radians": (math.pi, -math.pi / 2)}).compute()
    assert degrees.outputs["degrees"] == pytest.approx((180.0, -90.0))
    radians = NodeHarness("omni.graph.nodes.ToRad", inputs={"degrees": 90}).compute()
    assert radians.outputs["radians"] == pytest.approx(math.pi / 2)


@pytest.mark.parametrize("type_id, key, output, value, probe, expected", [
    ("omni.graph.nodes.EndsWith", "suffix", "isSuffix", "/World/robot/base_link", "_link", True),
    ("omni.graph.nodes.EndsWith", "suffix", "isSuffix", "/World/robot", "_link", False),
    ("omni.graph.nodes.EndsWith", "suffix", "isSuffix", "anything", "", True),
    ("omni.graph.nodes.StartsWith", "prefix", "isPrefix", "/World/robot", "/World", True),
    ("omni.graph.nodes.StartsWith", "prefix", "isPrefix", "/Env/robot", "/World", False),
])
def test_string_affix_tests(type_id, key, output, value, probe, expected):
    assert NodeHarness(type_id, inputs={"value": value, key: probe}).compute().outputs[output] is expected
