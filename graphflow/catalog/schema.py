"""The JSON Schema editors complete graph files with, generated from the registered node specs.

``graphflow schema -o FILE`` writes the graph format's schema (graphflow/schema/graph.schema.json)
with its ``nodes`` narrowed per node type: ``type`` lists every registered id (plugins included),
and each type's ``inputs`` lists its ports with their JSON types, defaults, ranges, lengths and
allowed tokens; execution ports are left out (they take connections, not values). So VS Code and
JetBrains complete node types and port names and flag wrong values as the compiler would.
"""
from __future__ import annotations

import copy
import json
import os

from graphflow.files import write_text
from graphflow.registry import Registry, default_registry
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import INTEGER_RANGES, SCALAR_KINDS, TUPLE_ROLES, parse_type

_SCALAR_SCHEMAS: dict[str, dict[str, object]] = {"bool": {"type": "boolean"}, "int": {"type": "integer"}, "uint": {"type": "integer", "minimum": 0},
                   "real": {"type": "number"}, "str": {"type": "string"}}


def graph_schema(registry: Registry | None = None) -> dict:
    """The graph format's JSON Schema with one ``if type == id then inputs ...`` rule per node type."""
    from graphflow.document import json_schema

    registry = registry or default_registry()
    schema = copy.deepcopy(json_schema())
    schema["$id"] = "graphflow-graph-with-node-types.json"
    node = schema["properties"]["nodes"]["items"]
    specs = [node_type.spec for node_type in registry.types()]
    ids = sorted({spec.id for spec in specs} | {alias for spec in specs for alias in spec.aliases})
    node["properties"]["type"] = {"enum": ids, "description": "A registered node type id (graphflow nodes)."}
    node["allOf"] = [_node_rule(spec) for spec in specs]
    return schema


def _node_rule(spec: NodeSpec) -> dict:
    inputs = {attribute.name: _port_schema(attribute) for attribute in spec.inputs
              if not attribute.is_execution and not attribute.attr_type.is_bundle}   # set by connections only
    return {
        "if": {"properties": {"type": {"enum": [spec.id, *spec.aliases]}}, "required": ["type"]},
        "then": {"properties": {
            "typeVersion": {"enum": sorted({spec.version, *spec.compatible_versions})},
            "inputs": {"type": "object", "properties": inputs, "additionalProperties": False,
                       "description": f"Inputs of {spec.id} (v{spec.version})."},
        }},
    }


def _port_schema(attribute: Attribute) -> dict:
    """JSON Schema of the values an input accepts (as ``Attribute.check`` accepts them)."""
    attr_type = parse_type(attribute.type)
    if attr_type.is_any:
        value: dict = {}
    elif attr_type.is_target:
        value = {"anyOf": [{"type": "string", "pattern": "^/"},
                           {"type": "array", "items": {"type": "string", "pattern": "^/"}}]}
    else:
        scalar = dict(_SCALAR_SCHEMAS[SCALAR_KINDS[TUPLE_ROLES.get(attr_type.base, attr_type.base)]])
        if attr_type.base in INTEGER_RANGES:
            low, high = INTEGER_RANGES[attr_type.base]
            scalar.update(minimum=low, maximum=high)
        if attribute.minimum is not None:
            scalar["minimum"] = attribute.minimum
        if attribute.maximum is not None:
            scalar["maximum"] = attribute.maximum
        if attribute.allowed_tokens:
            scalar["enum"] = list(attribute.allowed_tokens)
        value = scalar
        if attr_type.tuple_size:
            value = {"type": "array", "items": value, "minItems": attr_type.tuple_size, "maxItems": attr_type.tuple_size}
        if attr_type.is_array:
            value = {"type": "array", "items": value}
            if attribute.length is not None:
                value.update(minItems=attribute.length, maxItems=attribute.length)
    value["description"] = f"{attribute.type}: {attribute.description}".rstrip(": ")
    if attribute.default is not None:
        value["default"] = json.loads(json.dumps(attribute.default))
    return value


def write_schema(path: str | os.PathLike, *, force: bool = False, registry: Registry | None = None) -> None:
    write_text(path, json.dumps(graph_schema(registry), indent=2, sort_keys=True) + "\n", force=force)
