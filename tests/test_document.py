"""Graph documents: JSON round trip, atomic save, and every validation error reported at once."""
import json
import os

import pytest
from conftest import GRAPHS

from graphflow.document import (
    GraphError,
    dumps,
    json_schema,
    load_document,
    parse_document,
    save_document,
)


def _document(nodes, connections=(), **extra):
    return {"format": "graphflow", "formatVersion": [1, 0], "nodes": nodes, "connections": list(connections), **extra}


def _problems(data, source="bad.json"):
    with pytest.raises(GraphError) as caught:
        parse_document(data, source)
    return [str(p) for p in caught.value.problems]


def _graph_files():
    """Graph documents in graphs/ (key timelines and other JSON there are not graphs)."""
    return [p for p in sorted(GRAPHS.glob("*.json")) if json.loads(p.read_text()).get("format") == "graphflow"]


@pytest.mark.parametrize("path", _graph_files(), ids=lambda p: p.name)
def test_load_save_load_is_byte_identical(path, tmp_path):
    document = load_document(path)
    first = tmp_path / "first.json"
    save_document(document, first)
    second = tmp_path / "second.json"
    save_document(load_document(first), second)
    assert first.read_bytes() == second.read_bytes()
    assert first.read_text() == path.read_text(), "shipped graphs are saved in canonical form"


def test_saved_text_is_pretty_with_sorted_keys():
    document = parse_document(_document([{"type": "omni.graph.action.OnTick", "name": "tick"}]))
    text = dumps(document)
    assert text.endswith("\n")
    assert text.index('"format"') < text.index('"formatVersion"') < text.index('"nodes"')
    assert '\n  "nodes": [\n' in text


def test_failed_save_leaves_the_existing_file_untouched(tmp_path, monkeypatch):
    target = tmp_path / "graph.json"
    target.write_text("precious\n")
    document = parse_document(_document([{"name": "tick", "type": "omni.graph.action.OnTick"}]))

    def broken_fsync(_fd):
        raise OSError("disk full")

    monkeypatch.setattr(os, "fsync", broken_fsync)
    with pytest.raises(OSError):
        save_document(document, target)
    assert target.read_text() == "precious\n"
    assert [p.name for p in tmp_path.iterdir()] == ["graph.json"], "no temporary file is left behind"


def test_wrong_value_type_names_file_node_and_attribute():
    problems = _problems(_document([{"name": "gripper", "type": "omni.graph.action.Branch", "inputs": {"condition": "yes"}}]),
                         "pick.json")
    assert problems == ["pick.json: node 'gripper' input 'inputs:condition': expected bool, got \"yes\""]


def test_every_problem_of_a_file_is_reported_at_once():
    problems = _problems(_document(
        [{"name": "tick", "type": "omni.graph.action.OnTick"},
         {"name": "typo", "type": "omni.graph.action.Branchh"},
         {"name": "counter", "type": "omni.graph.action.Counter", "inputs": {"speed": 2}},
         {"name": "counter", "type": "omni.graph.action.Counter"},
         {"name": "delay", "type": "omni.graph.action.Delay", "inputs": {"duration": -1.0}},
         {"name": "add", "type": "omni.graph.nodes.Add"},
         {"name": "add2", "type": "omni.graph.nodes.Add"},
         {"name": "bool", "type": "omni.graph.nodes.ConstantBool"},
         {"name": "vec", "type": "omni.graph.nodes.ConstantDouble3"},
         {"name": "branch", "type": "omni.graph.action.Branch"}],
        [{"src": "tick.outputs:tick", "dst": "ghost.inputs:execIn"},
         {"src": "tick.outputs:nothing", "dst": "counter.inputs:execIn"},
         {"src": "add.outputs:sum", "dst": "add2.inputs:a"},
         {"src": "add2.outputs:sum", "dst": "add.inputs:a"},
         {"src": "vec.outputs:value", "dst": "branch.inputs:condition"},
         {"src": "bool.outputs:value", "dst": "add2.inputs:b"},
         {"src": "tick.outputs:deltaSeconds", "dst": "add2.inputs:b"},
         {"src": "tick.outputs:tick", "dst": "branch.inputs:condition"}]))
    expected_fragments = [
        "node 'typo': unknown node type 'omni.graph.action.Branchh' (did you mean 'omni.graph.action.Branch'?)",
        "node 'counter' input 'inputs:speed': omni.graph.action.Counter has no such input",
        "node 'counter': duplicate node name",
        "node 'delay' input 'inputs:duration': value -1.0 is below the minimum 0.0",
        "node 'ghost' connection 'inputs:execIn': dangling connection tick.outputs:tick -> ghost.inputs:execIn: no node named 'ghost'",
        "node 'tick' connection 'outputs:nothing': dangling connection",
        "node 'branch' connection 'inputs:condition': type mismatch in vec.outputs:value -> branch.inputs:condition: double[3] cannot feed bool",
        "node 'branch' connection 'inputs:condition': type mismatch in tick.outputs:tick -> branch.inputs:condition: execution cannot feed bool",
        "node 'add2' connection 'inputs:b': more than one source into a data input: bool.outputs:value, tick.outputs:deltaSeconds",
        "node 'add': data cycle: add -> add2 -> add",
    ]
    for fragment in expected_fragments:
        assert any(fragment in p for p in problems), f"missing: {fragment}\nin: {problems}"
    assert all(p.startswith("bad.json: ") for p in problems)
    assert len(problems) == len(expected_fragments)


def test_schema_problems_are_reported_with_their_location():
    problems = _problems({"format": "graphflow", "formatVersion": [1, 0],
                          "nodes": [{"name": "has space", "type": "omni.graph.action.OnTick"}, {"type": "x"}],
                          "extra": 1})
    assert any("Additional properties are not allowed ('extra'" in p for p in problems)
    assert any("nodes/0/name" in p and "has space" in p for p in problems)
    assert any("nodes/1" in p and "'name' is a required property" in p for p in problems)


def test_unsupported_format_major_version():
    problems = _problems({"format": "graphflow", "formatVersion": [2, 0], "nodes": []})
    assert problems == ["bad.json: formatVersion [2, 0] is not supported (this runtime reads 1.x)"]


def test_execution_inputs_cannot_take_values_and_variables_are_checked():
    problems = _problems(_document(
        [{"name": "branch", "type": "omni.graph.action.Branch", "inputs": {"execIn": 1}}],
        variables=[{"name": "speed", "type": "double", "default": "fast"}, {"name": "speed", "type": "vector"}]))
    assert "bad.json: node 'branch' input 'inputs:execIn': execution inputs take connections, not values" in problems
    assert "bad.json: variable 'speed': default: expected double, got \"fast\"" in problems
    assert "bad.json: variable 'speed': duplicate variable name" in problems
    assert "bad.json: variable 'speed': unknown attribute type 'vector'" in problems


def test_malformed_json_and_missing_file(tmp_path):
    broken = tmp_path / "broken.json"
    broken.write_text('{"format": "graphflow",\n  "nodes": [,]}')
    with pytest.raises(GraphError) as caught:
        load_document(broken)
    assert str(caught.value) == f"{broken}: malformed JSON at line 2 column 13: Expecting value"
    with pytest.raises(GraphError) as caught:
        load_document(tmp_path / "absent.json")
    assert str(caught.value).endswith("absent.json: file not found")


def test_legacy_alias_and_old_type_version_load():
    document = parse_document(_document([{"name": "tick", "type": "omni.graph.action.OnTick", "typeVersion": 2}]))
    assert document.node("tick").type_version == 2
    problems = _problems(_document([{"name": "tick", "type": "omni.graph.action.OnTick", "typeVersion": 99}]))
    assert problems == ["bad.json: node 'tick': typeVersion 99 of omni.graph.action.OnTick is not supported (this runtime has version 2)"]


def test_published_schema_is_valid_json_schema():
    import jsonschema

    jsonschema.Draft202012Validator.check_schema(json_schema())
    packaged = GRAPHS.parent / "graphflow" / "schema" / "graph.schema.json"
    assert json.loads(packaged.read_text()) == json_schema()


def test_non_finite_input_values_are_saved_as_the_strings_that_load_back():
    from graphflow.document import dumps

    document = parse_document({"format": "graphflow", "formatVersion": [1, 0], "nodes": [
        {"name": "c", "type": "omni.graph.nodes.ConstantDouble3", "inputs": {"value": [float("nan"), float("inf"), 1.0]}}]})
    text = dumps(document)
    assert '"nan"' in text and '"inf"' in text and "NaN" not in text and "Infinity" not in text
    assert parse_document(json.loads(text)).node("c").inputs["value"] == ["nan", "inf", 1.0]
