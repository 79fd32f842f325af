"""The rest of og.Controller that Isaac scripts call around edit: lookups (node, attribute, graph), get and set,
Controller objects, create_graph/create_node, evaluate_sync; behaviour from Kit's omni.graph.core reference."""
import asyncio
import itertools
import warnings

import pytest

from graphflow.build import og
from graphflow.errors import BadInput
from graphflow.testing.harness import GraphHarness

_paths = (f"/World/LookupGraph{n}" for n in itertools.count())   # og keeps graphs by path: one per test


def built(path):
    keys = og.Controller.Keys
    return og.Controller.edit({"graph_path": path, "evaluator_name": "execution"}, {keys.CREATE_NODES: [
        ("tick", "omni.graph.action.OnTick"), ("text", "graphflow.FormatText")]})


def test_node_and_attribute_look_up_built_nodes_by_path_tuple_or_handle():
    path = next(_paths)
    graph, (tick, text), _, _ = built(path)
    node = og.Controller.node(f"{path}/text")
    assert node.get_prim_path() == f"{path}/text" and node.get_type_name() == "graphflow.FormatText"
    assert og.Controller.node(("tick", graph)).get_prim_path() == f"{path}/tick"
    assert og.Controller.node_path(text) == f"{path}/text"
    for spelling in [(f"{path}/text.inputs:format",), ("inputs:format", text), (("inputs:format", text),),
                     ("inputs:format", f"{path}/text")]:
        assert og.Controller.attribute(*spelling).get_path() == f"{path}/text.inputs:format"
    assert og.Controller.attribute_path("inputs:format", node) == f"{path}/text.inputs:format"
    assert node.get_attribute("outputs:text").get_node().get_prim_path() == f"{path}/text"
    assert og.Controller.graph(path) is graph and og.Controller.graph({"graph_path": path}) is graph
    assert og.Controller.graph("/World/NoSuchGraph") is None          # Kit answers None, not an error
    with pytest.raises(BadInput, match=f"og.Controller.node: no node '{path}/nothing'"):
        og.Controller.node(f"{path}/nothing")
    with pytest.raises(BadInput, match="has no attribute 'inputs:nothing'"):
        node.get_attribute("inputs:nothing")


def test_get_answers_the_authored_value_else_the_declared_default_and_set_before_run_is_what_runs():
    path = next(_paths)
    graph, (tick, text), _, _ = built(path)
    fmt = og.Controller.attribute("inputs:format", text)
    declared = text.spec.attribute("inputs:format").default
    assert og.Controller.get(fmt) == declared                        # nothing authored: the node type's default
    og.Controller.set(fmt, "t = {value}")
    og.Controller.set(og.Controller.attribute(f"{path}/text.inputs:value"), 2.5)
    assert og.Controller.get(fmt) == "t = {value}" and og.Controller(fmt).get() == "t = {value}"
    assert og.Controller.get(f"{path}/text.inputs:value") == 2.5
    og.Controller.edit(path, {og.Controller.Keys.CREATE_NODES: [("show", "omni.graph.ui_nodes.PrintText")],
                              og.Controller.Keys.CONNECT: [("tick.outputs:tick", "show.inputs:execIn"),
                                                           ("text.outputs:text", "show.inputs:text")]})
    harness = GraphHarness(graph.document)
    harness.run(1)
    assert harness.output("text", "text") == "t = 2.5"              # what the script set is what runs


def test_a_controller_object_keeps_its_graph_across_edits_and_its_attribute_for_get_and_set():
    """Kit: ``new_controller = og.Controller(graph); new_controller.edit(cmds())`` edits that graph."""
    keys, path = og.Controller.Keys, next(_paths)
    controller = og.Controller()
    graph, *_ = controller.edit(path, {keys.CREATE_NODES: [("tick", "omni.graph.action.OnTick")]})
    again, (text,), _, _ = controller.edit({keys.CREATE_NODES: [("text", "graphflow.FormatText")]})
    assert again is graph and [n.name for n in graph.nodes()] == ["tick", "text"]
    other = og.Controller(graph)
    other.edit({keys.SET_VALUES: [("text.inputs:format", "{value} m")]})
    value = og.Controller(og.Controller.attribute("inputs:value", text))
    value.set(4.0)
    assert value.get() == 4.0 and graph.document.node("text").inputs == {"format": "{value} m", "value": 4.0}
    made = og.Controller()
    made.edit({"graph_path": next(_paths), "evaluator_name": "execution"})       # the graph first, commands later
    made.edit(edit_commands={keys.CREATE_NODES: [("tick", "omni.graph.action.OnTick")]})
    assert [n.name for n in made.graph_id.nodes()] == ["tick"]
    with pytest.raises(BadInput, match="no graph given"):
        og.Controller().edit({keys.CREATE_NODES: []})


def test_create_graph_create_node_and_connect_build_what_edit_would():
    path = next(_paths)
    graph = og.Controller.create_graph({"graph_path": path, "evaluator_name": "execution"})
    tick = og.Controller.create_node(f"{path}/tick", "omni.graph.action.OnTick")
    count = og.Controller.create_node(("count", graph), "omni.graph.action.Counter")
    og.Controller.connect(tick.get_attribute("outputs:tick"), count.get_attribute("inputs:execIn"))
    assert [(c.src, c.dst) for c in graph.document.connections] == [("tick.outputs:tick", "count.inputs:execIn")]
    harness = GraphHarness(graph.document)
    harness.run(3)
    assert harness.output("count", "count") == 3
    og.Controller.delete_node(f"{path}/count")
    assert not count.is_valid() and graph.document.connections == ()
    with pytest.raises(BadInput, match="the graph '/World/Elsewhere' does not exist"):
        og.Controller.create_node("/World/Elsewhere/tick", "omni.graph.action.OnTick")
    with pytest.raises(BadInput, match="'tick' names no graph"):
        og.Controller.create_node("tick", "omni.graph.action.OnTick")


def test_evaluate_sync_builds_nothing_more_and_says_graphflow_run_evaluates_in_one_line():
    path = next(_paths)
    graph, *_ = built(path)
    before = graph.dumps()
    with pytest.warns(og.OgCompatWarning, match=rf"evaluate\({path}\): not evaluated here.*graphflow run") as lines:
        og.Controller.evaluate_sync(graph)
    assert len(lines) == 1 and "\n" not in str(lines[0].message) and graph.dumps() == before
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", og.OgCompatWarning)
        og.Controller(path).evaluate_sync()                        # an object evaluates its own graph
    with pytest.warns(og.OgCompatWarning, match=rf"evaluate\({path}\): not evaluated here"):
        asyncio.run(og.Controller(graph).evaluate())              # awaited, as Kit's async tests do
    with pytest.raises(BadInput, match="the graph '/World/NotBuilt' does not exist"):
        og.Controller.evaluate_sync("/World/NotBuilt")             # Kit raises for a graph that is not there


def test_both_controllers_share_kits_keys_and_keys_not_built_here_are_refused_with_one_line():
    assert og.GraphController.Keys is og.Controller.Keys
    with pytest.raises(BadInput, match="create_prims not supported here"):
        og.Controller.edit(next(_paths), {og.Controller.Keys.CREATE_PRIMS: [("/World/Cube", "Cube")]})


def test_disconnect_all_breaks_every_connection_of_an_attribute_and_attribute_set_authors_it():
    keys, path = og.Controller.Keys, next(_paths)
    graph, (tick, text), _, _ = built(path)
    og.Controller.edit(path, {keys.CREATE_NODES: [("one", "omni.graph.ui_nodes.PrintText"),
                                                  ("two", "omni.graph.ui_nodes.PrintText")],
                              keys.CONNECT: [("tick.outputs:tick", "one.inputs:execIn"),
                                             ("tick.outputs:tick", "two.inputs:execIn"),
                                             ("text.outputs:text", "one.inputs:text")]})
    og.Controller.edit(path, {keys.DISCONNECT_ALL: f"{path}/tick.outputs:tick"})
    assert [(c.src, c.dst) for c in graph.document.connections] == [("text.outputs:text", "one.inputs:text")]
    og.Controller.disconnect_all(("inputs:text", og.Controller.node(f"{path}/one")))
    assert graph.document.connections == ()
    og.Controller.attribute(f"{path}/text.inputs:format").set("{value} s")
    assert graph.document.node("text").inputs == {"format": "{value} s"}
    assert graph in og.get_all_graphs()


def test_variables_take_kits_type_spellings_and_a_compound_node_is_refused_with_one_line():
    """Kit's edit docs: ``keys.CREATE_VARIABLES: [("velocity", "float3"), ("count", og.Type(og.BaseDataType.FLOAT), 4)]``."""
    keys, path = og.Controller.Keys, next(_paths)
    graph, *_ = og.Controller.edit(path, {keys.CREATE_VARIABLES: [
        ("velocity", "float3"), ("count", og.Type(og.BaseDataType.FLOAT), 4), ("names", "token[]"),
        ("heading", og.Type(og.BaseDataType.DOUBLE, 3, 0, og.AttributeRole.VECTOR)),
        ("label", og.Type(og.BaseDataType.UCHAR, 1, 1, og.AttributeRole.TEXT)), ("spin", "quatd")]})
    assert {v.name: v.type for v in graph.document.variables} == {
        "velocity": "float[3]", "count": "float", "names": "token[]", "heading": "vectord[3]", "label": "string",
        "spin": "quatd[4]"}
    harness = GraphHarness(graph.document)
    assert harness.instance.variables["count"] == 4.0
    with pytest.raises(BadInput, match="node 'inner': dict as its type: compound nodes .* are not built here"):
        og.Controller.edit(path, {keys.CREATE_NODES: [("inner", {keys.CREATE_NODES: [("t", "omni.graph.action.OnTick")]})]})


def test_a_node_answers_its_graph_and_every_port_and_attributes_key_by_path():
    """Kit's og.Node.get_graph/get_attributes, og.Attribute.get_name and attributes usable as dict keys; OnTick's
    ports as Kit's node library reference lists them; og.Controller.create_variable adds a graph variable."""
    path = next(_paths)
    graph, (tick, _text), _, _ = built(path)
    node = og.Controller.node(f"{path}/tick")
    assert node.get_graph() is graph
    names = [attribute.get_name() for attribute in node.get_attributes()]
    assert set(names) == {"inputs:framePeriod", "inputs:onlyPlayback", "outputs:tick", "outputs:deltaSeconds",
                          "outputs:time", "outputs:frame", "outputs:timeSinceStart", "outputs:absoluteSimTime",
                          "outputs:isPlaying"}
    seen = {node.get_attribute("inputs:onlyPlayback"): "first"}
    assert seen[og.Controller.attribute(f"{path}/tick.inputs:onlyPlayback")] == "first"   # equal and same hash
    assert node.get_attribute("inputs:onlyPlayback") != node.get_attribute("inputs:framePeriod")
    og.Controller.create_variable(path, "speed", "double")
    assert {v.name: v.type for v in graph.document.variables}["speed"] == "double"
