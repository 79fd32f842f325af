"""Editor support: the generated JSON Schema knows every node type's inputs and agrees with the compiler;
graph files carry "$schema" and graphflow new writes the schema they name."""
import json
import types

import jsonschema
import pytest
from conftest import GRAPHS

from graphflow.catalog.schema import graph_schema
from graphflow.cli import main
from graphflow.document import parse_document
from graphflow.model import GraphError
from graphflow.registry import Registry, default_registry
from graphflow.spec import Attribute, NodeSpec


@pytest.fixture(scope="module")
def validator():
    return jsonschema.Draft202012Validator(graph_schema())


def graph(*nodes, connections=()):
    return {"format": "graphflow", "formatVersion": [1, 0], "nodes": list(nodes), "connections": list(connections)}


def schema_errors(validator, data) -> list[str]:
    return ["/".join(map(str, error.absolute_path)) for error in validator.iter_errors(data)]


def compiler_refuses(data) -> str:
    with pytest.raises(GraphError) as caught:
        parse_document(data, "cell.json")
    return str(caught.value)


def test_every_shipped_graph_is_valid_under_the_generated_schema(validator):
    shipped = [p for p in sorted(GRAPHS.rglob("*.json")) if json.loads(p.read_text()).get("format") == "graphflow"]
    assert len(shipped) >= 10
    for path in shipped:
        assert schema_errors(validator, json.loads(path.read_text())) == [], path.name


COMPARE, TEXT = "omni.graph.nodes.Compare", "graphflow.FormatText"


@pytest.mark.parametrize("node_type, inputs, schema_flags, refused_by_compiler", [
    (COMPARE, {"operation": "=!"}, "nodes/0/inputs/operation", "expected one of"),   # a token not allowed
    (COMPARE, {"operatoin": "=="}, "nodes/0/inputs", "has no such input"),           # a misspelled port
    (TEXT, {"format": 3}, "nodes/0/inputs/format", "node 'n' input 'inputs:format'"),  # a number for a string
])
def test_the_schema_flags_what_the_compiler_refuses(validator, node_type, inputs, schema_flags, refused_by_compiler):
    data = graph({"name": "n", "type": node_type, "inputs": inputs})
    assert schema_errors(validator, data) == [schema_flags]
    assert refused_by_compiler in compiler_refuses(data)


def test_ranges_tuple_lengths_and_node_types_are_in_the_schema(validator):
    schema = graph_schema()
    rules = {rule["if"]["properties"]["type"]["enum"][0]: rule["then"]["properties"]
             for rule in schema["properties"]["nodes"]["items"]["allOf"]}
    assert len(rules) == len(default_registry().types())
    placing = rules["graphflow.PickPlaceController"]["inputs"]["properties"]["placingPosition"]
    assert placing["minItems"] == placing["maxItems"] == 3 and placing["items"]["type"] == "number"
    assert "execIn" not in rules["omni.graph.action.Counter"]["inputs"]["properties"]   # connections only
    assert rules["omni.graph.nodes.ReadPrimAttribute"]["typeVersion"] == {"enum": [1, 2, 3]}
    misspelled = graph({"name": "tick", "type": "omni.graph.action.OnTik"})
    assert schema_errors(validator, misspelled) == ["nodes/0/type"]


def test_plugin_node_types_are_in_the_schema():
    registry = Registry()
    pump = types.ModuleType("acme_pump")
    pump.SPEC = NodeSpec(id="acme.Pump", version=1, description="A pump.", inputs=(
        Attribute("rate", "double", default=1.0, minimum=0.0, maximum=5.0, description="litres per second"),))
    pump.compute = lambda db: True
    registry.register_module(pump)
    validator = jsonschema.Draft202012Validator(graph_schema(registry))
    assert schema_errors(validator, graph({"name": "p", "type": "acme.Pump", "inputs": {"rate": 2.5}})) == []
    assert schema_errors(validator, graph({"name": "p", "type": "acme.Pump", "inputs": {"rate": 7}})) \
        == ["nodes/0/inputs/rate"]


def test_graphflow_new_writes_the_schema_its_graph_names(tmp_path, monkeypatch, capsys):
    monkeypatch.chdir(tmp_path)
    assert main(["new", "starter"]) == 0
    starter = json.loads((tmp_path / "starter.json").read_text())
    schema = json.loads((tmp_path / starter["$schema"]).read_text())
    assert jsonschema.Draft202012Validator(schema).is_valid(starter)
    assert main(["schema", "-o", "graphflow.schema.json"]) == 2   # never overwritten without --force
    assert main(["schema", "-o", "graphflow.schema.json", "--force"]) == 0

