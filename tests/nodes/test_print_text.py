"""omni.graph.ui_nodes.PrintText and graphflow.FormatText."""
import logging

import pytest

from graphflow.document import GraphError
from graphflow.executor import GraphRuntimeError
from graphflow.testing import ExecState, GraphHarness, NodeHarness


def test_print_logs_text_and_fires_exec_out():
    h = NodeHarness("omni.graph.ui_nodes.PrintText", inputs={"text": "hello"})
    r = h.compute("execIn")
    assert r.exec_states["execOut"] == ExecState.ENABLED
    assert h.logs == ["hello"]
    assert h.compute().fired == set()  # no pulse: nothing printed
    assert h.logs == ["hello"]


@pytest.mark.parametrize("token, level", [("Info", "info"), ("Warning", "warning"), ("Error", "error")])
def test_log_level_reaches_the_event_log_and_python_logging(token, level, caplog):
    h = NodeHarness("omni.graph.ui_nodes.PrintText", inputs={"text": "x", "logLevel": token})
    with caplog.at_level(logging.DEBUG, logger="graphflow.graph"):
        h.compute("execIn")
    assert [e.level for e in h.instance.events] == [level]
    assert caplog.records[-1].levelname == level.upper()
    assert "x" in caplog.records[-1].getMessage()


def test_unknown_log_level_is_rejected_at_load():
    with pytest.raises(GraphError, match="inputs:logLevel"):
        NodeHarness("omni.graph.ui_nodes.PrintText", inputs={"logLevel": "Debug"})


def test_format_text():
    def fmt(fmt, value):
        return NodeHarness("graphflow.FormatText", inputs={"format": fmt, "value": value}).compute().outputs["text"]
    assert fmt("count = {value}", 3) == "count = 3"
    assert fmt("x = {value:.3f}", 0.12345) == "x = 0.123"
    assert fmt("{}", "plain") == "plain"
    assert fmt("first = {value[0]}", [4, 5]) == "first = 4"
    assert NodeHarness("graphflow.FormatText", inputs={"value": 1.5}).compute().outputs["text"] == "1.5"


def test_bad_format_is_an_error_naming_the_input():
    with pytest.raises(GraphRuntimeError, match="inputs:format"):
        NodeHarness("graphflow.FormatText", inputs={"format": "{missing}", "value": 1}).compute()


def test_counter_format_print_logs_in_tick_order():
    g = GraphHarness({
        "nodes": [
            {"name": "tick", "type": "omni.graph.action.OnTick"},
            {"name": "cnt", "type": "omni.graph.action.Counter"},
            {"name": "fmt", "type": "graphflow.FormatText", "inputs": {"format": "count = {value}"}},
            {"name": "print", "type": "omni.graph.ui_nodes.PrintText"},
        ],
        "connections": [
            {"src": "tick.outputs:tick", "dst": "cnt.inputs:execIn"},
            {"src": "cnt.outputs:execOut", "dst": "print.inputs:execIn"},
            {"src": "cnt.outputs:count", "dst": "fmt.inputs:value"},
            {"src": "fmt.outputs:text", "dst": "print.inputs:text"},
        ],
    })
    g.run(ticks=3)
    assert g.logs == ["count = 1", "count = 2", "count = 3"]


def test_string_nodes_append_join_and_measure():
    from graphflow.testing import NodeHarness

    def out(type_id, output, **inputs):
        return NodeHarness(f"omni.graph.nodes.{type_id}", inputs).compute().outputs[output]

    assert out("BuildString", "value", a="robot_", b="arm") == "robot_arm"
    assert out("BuildString", "value", a=["a", "b"], b="_x") == ("a_x", "b_x")
    assert out("AppendString", "value", value="/World", suffix="/Cube") == "/World/Cube"
    assert out("JoinString", "string", delimiter=", ", elements=["x", "y", "z"]) == "x, y, z"
    assert out("GetStringLength", "length", string="graphflow") == 9


def test_capitalize_string_operations():
    from graphflow.testing import NodeHarness

    cases = {"UpperCase": "ROBOT ARM", "LowerCase": "robot arm", "Capitalize": "Robot arm", "Title": "Robot Arm"}
    for operation, expected in cases.items():
        node = NodeHarness("omni.graph.nodes.CapitalizeString", {"operation": operation, "string": "roBOT arm"})
        assert node.compute().outputs["string"] == expected


def test_parent_and_appended_paths():
    from graphflow.testing import NodeHarness

    parent = NodeHarness("omni.graph.nodes.GetParentPath", {"path": ["/World/Cube", "/World"]}).compute()
    assert parent.outputs["parentPath"] == ("/World", "/")
    appended = NodeHarness("omni.graph.nodes.AppendPath", {"path": "/World", "suffix": "Cube.attr"}).compute()
    assert appended.outputs["path"] == "/World/Cube.attr"
