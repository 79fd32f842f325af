"""omni.graph.nodes.BooleanAnd / BooleanOr / BooleanNot."""
import pytest

from graphflow.executor import GraphRuntimeError
from graphflow.testing import NodeHarness


@pytest.mark.parametrize("a, b", [(False, False), (False, True), (True, False), (True, True)])
def test_truth_tables(a, b):
    inputs = {"a": a, "b": b}
    assert NodeHarness("omni.graph.nodes.BooleanAnd", inputs=inputs).compute().outputs["result"] is (a and b)
    assert NodeHarness("omni.graph.nodes.BooleanOr", inputs=inputs).compute().outputs["result"] is (a or b)


def test_not():
    assert NodeHarness("omni.graph.nodes.BooleanNot", inputs={"valueIn": True}).compute().outputs["valueOut"] is False
    assert NodeHarness("omni.graph.nodes.BooleanNot").compute().outputs["valueOut"] is True  # unset reads false


def test_arrays_elementwise_and_single_bool_broadcast():
    r = NodeHarness("omni.graph.nodes.BooleanAnd", inputs={"a": [True, False, True], "b": True}).compute()
    assert r.outputs["result"] == (True, False, True)
    r = NodeHarness("omni.graph.nodes.BooleanOr", inputs={"a": [True, False], "b": [False, False]}).compute()
    assert r.outputs["result"] == (True, False)
    r = NodeHarness("omni.graph.nodes.BooleanNot", inputs={"valueIn": [True, False]}).compute()
    assert r.outputs["valueOut"] == (False, True)


def test_non_bool_is_an_error():
    with pytest.raises(GraphRuntimeError, match="inputs:a must hold bools"):
        NodeHarness("omni.graph.nodes.BooleanAnd", inputs={"a": 0.5, "b": True}).compute()


@pytest.mark.parametrize("name, truth", [("AND", (0, 0, 0, 1)), ("OR", (0, 1, 1, 1)), ("XOR", (0, 1, 1, 0)),
                                         ("NAND", (1, 1, 1, 0)), ("NOR", (1, 0, 0, 0)), ("XNOR", (1, 0, 0, 1))])
def test_boolean_expression_truth_tables(name, truth):
    cases = [(False, False), (False, True), (True, False), (True, True)]
    got = tuple(int(NodeHarness("omni.graph.nodes.BooleanExpr", {"a": a, "b": b, "operator": name})
                    .compute().outputs["result"]) for a, b in cases)
    assert got == truth



@pytest.mark.parametrize("type_id, truth", [("BooleanXor", (0, 1, 1, 0)), ("BooleanNand", (1, 1, 1, 0)),
                                            ("BooleanNor", (1, 0, 0, 0))])
def test_xor_nand_nor_truth_tables_and_arrays(type_id, truth):
    cases = [(False, False), (False, True), (True, False), (True, True)]
    node = f"omni.graph.nodes.{type_id}"
    assert tuple(int(NodeHarness(node, {"a": a, "b": b}).compute().outputs["result"]) for a, b in cases) == truth
    pairwise = NodeHarness(node, {"a": [a for a, _ in cases], "b": [b for _, b in cases]}).compute()
    assert tuple(int(r) for r in pairwise.outputs["result"]) == truth


def test_select_if_picks_whole_values_or_element_by_element():
    assert NodeHarness("omni.graph.nodes.SelectIf", {"condition": True, "ifTrue": 1.5, "ifFalse": -1.0}
                       ).compute().outputs["result"] == 1.5
    picked = NodeHarness("omni.graph.nodes.SelectIf", {"condition": [True, False, True], "ifTrue": [1, 2, 3],
                                                       "ifFalse": 0}).compute().outputs["result"]
    assert picked == (1, 0, 3)
