"""graphflow.build.Graph: each call is checked by the compiler at once, refusals name node and port and
change nothing, and what it saves is the canonical file graphflow reads."""
import json
from pathlib import Path

import pytest
from conftest import GRAPHS

from graphflow.build import Graph
from graphflow.cli import main
from graphflow.model import GraphError

SHIPPED = sorted(GRAPHS.glob("*.json")) + sorted((GRAPHS / "scenarios").glob("*.json"))
SHIPPED = [path for path in SHIPPED if json.loads(path.read_text()).get("format") == "graphflow"]   # not key / topic files


def counter_graph() -> Graph:
    graph = Graph(settings={"duration": 1.0, "timeStep": 0.1})
    tick = graph.node("tick", "omni.graph.action.OnTick")
    count = graph.node("count", "omni.graph.action.Counter")
    graph.connect(tick.outputs.tick, count.inputs.execIn)
    return graph


def refused(graph: Graph, call, *args, **kwargs) -> str:
    """The one line a refused call raises; the graph must be exactly as before it."""
    before = graph.dumps()
    with pytest.raises(GraphError) as caught:
        call(*args, **kwargs)
    assert graph.dumps() == before
    assert len(caught.value.problems) == 1
    return str(caught.value)


def test_refusals_name_the_node_and_port_and_change_nothing():
    graph = counter_graph()
    assert "node 'x': unknown node type 'omni.graph.action.OnTik' (did you mean 'omni.graph.action.OnTick'?)" in \
        refused(graph, graph.node, "x", "omni.graph.action.OnTik")
    assert "node 'count'" in refused(graph, graph.node, "count", "omni.graph.action.OnTick")
    message = refused(graph, graph.connect, "tick.outputs:tick", "count.inputs:execInn")
    assert "node 'count'" in message and "execInn" in message and "execIn, reset" in message
    message = refused(graph, graph.set, "count.inputs:execIn", 1)
    assert "node 'count' input 'inputs:execIn': execution inputs take connections, not values" in message
    message = refused(graph, graph.connect, "count.inputs:execIn", "tick.outputs:tick")
    assert "'count.inputs:execIn' is not an output" in message
    assert "already connected" in refused(graph, graph.connect, "tick.outputs:tick", "count.inputs:execIn")
    assert "no such node" in refused(graph, graph.delete, "nobody")


def test_values_are_checked_against_the_spec_range_and_tokens():
    graph = counter_graph()
    compare = graph.node("compare", "omni.graph.nodes.Compare")
    message = refused(graph, compare.set, operation="=!")
    assert "node 'compare' input 'inputs:operation': expected one of" in message
    graph.node("text", "graphflow.FormatText")
    message = refused(graph, graph.connect, "count.outputs:execOut", "text.inputs:value")
    assert "node 'text'" in message and "type mismatch" in message
    compare.set(operation="==", b=4)
    assert graph.document.node("compare").inputs == {"operation": "==", "b": 4}


def test_delete_removes_the_nodes_connections_and_disconnect_one():
    graph = counter_graph()
    graph.node("print", "omni.graph.ui_nodes.PrintText", text="hi")
    graph.connect("count.outputs:execOut", "print.inputs:execIn")
    graph.disconnect("tick.outputs:tick", "count.inputs:execIn")
    assert [c.src for c in graph.document.connections] == ["count.outputs:execOut"]
    graph.delete("count")
    assert [n.name for n in graph.document.nodes] == ["tick", "print"]
    assert graph.document.connections == ()
    assert "not connected" in refused(graph, graph.disconnect, "tick.outputs:tick", "print.inputs:execIn")


def test_handles_list_their_ports_for_completion():
    graph = counter_graph()
    count = graph["count"]
    assert dir(count.inputs) == ["execIn", "reset"]
    assert str(count.outputs.count) == "count.outputs:count" and count.outputs.count.type == "int"
    with pytest.raises(AttributeError, match="node 'count' has no output 'total'"):
        count.outputs.total


def test_variables_and_checks_are_checked_too():
    graph = counter_graph()
    graph.variable("speed", "double", 0.5)
    assert "variable 'speed'" in refused(graph, graph.variable, "speed", "double")
    message = refused(graph, graph.variable, "bad", "double", "fast")
    assert "variable 'bad'" in message
    graph.check("stopsBy", time=1.0)
    message = refused(graph, graph.check, "stopsBy", time="soon")
    assert "checks/1" in message
    assert graph.document.checks[0]["time"] == 1.0


@pytest.mark.parametrize("path", SHIPPED, ids=lambda p: p.name)
def test_load_then_save_is_byte_identical(path, tmp_path):
    graph = Graph.load(path)
    assert graph.dumps() == path.read_text(encoding="utf-8")


def test_saved_graph_validates_and_runs(tmp_path, capsys):
    graph = counter_graph()
    text = graph.node("text", "graphflow.FormatText", format="tick {value}")
    show = graph.node("show", "omni.graph.ui_nodes.PrintText")
    graph.connect(graph["count"].outputs.count, text.inputs.value)
    graph.connect(text.outputs.text, show.inputs.text)
    graph.connect("count.outputs:execOut", "show.inputs:execIn")
    path = graph.save(tmp_path / "counter.json")
    assert json.loads(Path(path).read_text())["$schema"] == "graphflow.schema.json"
    assert main(["validate", str(path)]) == 0
    assert main(["run", str(path)]) == 0
    printed = [line for line in capsys.readouterr().out.splitlines() if line.startswith("tick ")]
    assert printed == [f"tick {n}" for n in range(1, 11)]   # 1 s at 0.1 s a tick: ten ticks, counted from 1
    assert Graph.load(path).dumps() == Path(path).read_text()
