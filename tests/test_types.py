"""Attribute types: parsing, coercion of JSON values, and which connections are allowed."""
import math

import pytest

from graphflow.types import ExecState, TypeMismatch, can_connect, parse_type


@pytest.mark.parametrize("name, value, expected", [
    ("bool", True, True),
    ("int", 3, 3),
    ("int", 4.0, 4),
    ("uint", 7, 7),
    ("double", 2, 2.0),
    ("float", 0.5, 0.5),
    ("token", "Open", "Open"),
    ("double[3]", [1, 2, 3], (1.0, 2.0, 3.0)),
    ("quatd[4]", [0, 0, 0, 1], (0.0, 0.0, 0.0, 1.0)),
    ("int[2]", [1, 2], (1, 2)),
    ("double[]", [0.5, 1], (0.5, 1.0)),
    ("token[]", ["a", "b"], ("a", "b")),
    ("double[3][]", [[1, 2, 3], [4, 5, 6]], ((1.0, 2.0, 3.0), (4.0, 5.0, 6.0))),
    ("target", "/World/Cube", ("/World/Cube",)),
    ("target", ["/A", "/B"], ("/A", "/B")),
    ("any", [1, [2, 3]], (1, (2, 3))),
])
def test_coerces_json_values(name, value, expected):
    assert parse_type(name).coerce(value) == expected


def test_nan_is_a_double():
    assert math.isnan(parse_type("double").coerce("nan"))


@pytest.mark.parametrize("name, value, message", [
    ("bool", "yes", 'expected bool, got "yes"'),
    ("bool", 1, "expected bool, got 1"),
    ("int", 1.5, "expected int, got 1.5"),
    ("int", True, "expected int, got true"),
    ("uint", -1, "expected uint (0 to 4294967295), got -1"),
    ("double", "fast", 'expected double, got "fast"'),
    ("double[3]", [1, 2], "expected double[3], got [1, 2]"),
    ("token[]", "a", 'expected token[], got "a"'),
    ("target", "World/Cube", "absolute prim paths"),
])
def test_rejects_values_with_a_clear_reason(name, value, message):
    with pytest.raises(TypeMismatch) as caught:
        parse_type(name).coerce(value)
    assert message in str(caught.value)


@pytest.mark.parametrize("name", ["vector", "double[5]", "token[3]", "double[3", "quatd", "colour"])
def test_unknown_type_names(name):
    with pytest.raises(ValueError):
        parse_type(name)


@pytest.mark.parametrize("source, destination, allowed", [
    ("execution", "execution", True),
    ("execution", "bool", False),
    ("bool", "execution", False),
    ("int", "double", True),
    ("double", "float", True),
    ("double", "bool", False),
    ("double[3]", "double[3]", True),
    ("double[3]", "double[4]", False),
    ("double[]", "double", False),
    ("any", "double[3]", True),
    ("token[]", "any", True),
    ("token", "string", True),
    ("token", "target", True),
    ("double", "target", False),
])
def test_connection_compatibility(source, destination, allowed):
    assert can_connect(parse_type(source), parse_type(destination)) is allowed


def test_defaults_per_type():
    assert parse_type("execution").default_value() is ExecState.DISABLED
    assert parse_type("double[3]").default_value() == (0.0, 0.0, 0.0)
    assert parse_type("token[]").default_value() == ()
    assert parse_type("target").default_value() == ()
    assert parse_type("bool").default_value() is False
