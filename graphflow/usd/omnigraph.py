"""Bring Isaac Sim action graphs over: an OmniGraph prim in a USD stage -> a graphflow document.

usd-core composes what Kit left in the file (list-op residue such as
``delete``/``prepend`` on connections, relative connection and relationship
paths), so the importer reads composed values only. Node type ids go through
the registry (legacy ids resolve through aliases); inputs graphflow's node does
not declare are dropped with a warning; unknown node types are errors unless
the caller asks to skip them (their connections go too). The import degrades
rather than refuses: an input naming a prim of a layer that cannot be opened
is kept and named (node_mapping.missing_target), any typeVersion loads
(graph_parts.map_version), and every graph of the file is imported with its
variables (graph_parts).
"""
from __future__ import annotations

import math
import os
from dataclasses import dataclass, field, replace
from pathlib import Path

from graphflow.document import (
    FORMAT_NAME,
    FORMAT_VERSION,
    GraphDocument,
    GraphError,
    parse_document,
)
from graphflow.errors import BadInput
from graphflow.registry import Registry, default_registry
from graphflow.usd.bundle_ports import DYNAMIC_INPUTS, expand, input_sources
from graphflow.usd.graph_parts import (
    INSTANCE_TOKEN,
    NODE_PATH_READERS,
    PORT_CHANGES,
    bind_target,
    graph_prefixes,
    graph_targets,
    graph_variables,
    map_version,
    prefixed,
)
from graphflow.usd.node_eras import era_inputs, era_of, upgraded_values
from graphflow.usd.node_mapping import (
    GENERIC_PUBLISHERS,
    GENERIC_SUBSCRIBERS,
    LEGACY_GRIPPER_COMMANDS,
    LEGACY_GRIPPER_ID,
    PICK_PLACE_ID,
    PICK_PLACE_OLD_INPUTS,
    RENDERING_NODES,
    gather_message_fields,
    is_legacy_surface_gripper,
    legacy_gripper_command_node,
    legacy_gripper_renames,
    map_legacy_surface_gripper,
    map_old_pick_place,
    message_field,
    missing_target,
)

GRAPH_TYPE = "OmniGraph"
NODE_TYPE = "OmniGraphNode"
UI_POSITION = "ui:nodegraph:node:pos"
EXTENDED_VALUE = "omni:graph:attrValue"


class ImportProblem(BadInput):
    """The stage or graph cannot be imported; ``problems`` lists every reason, one line each."""

    def __init__(self, problems: list[str]):
        self.problems = problems
        super().__init__("\n".join(problems))


@dataclass
class ImportResult:
    document: GraphDocument
    graph_path: str
    warnings: list[str] = field(default_factory=list)


def find_graphs(stage) -> list[str]:
    """Paths of every OmniGraph prim in the stage, in stage order."""
    return [str(prim.GetPath()) for prim in stage.Traverse() if prim.GetTypeName() == GRAPH_TYPE]


def import_graph(stage_path: str, *, graph_path: str | None = None, output_path: str | None = None,
                 skip_unknown: bool = False, registry: Registry | None = None) -> ImportResult:
    """Convert the OmniGraphs of a USD file (or the one at *graph_path*) into one validated graphflow document.

    The document's ``settings.stage`` points at the USD file (relative to
    *output_path*'s folder when given), so the imported graph runs on the stage it came from.
    Kit evaluates every graph of a stage: without *graph_path* all of them are imported, their
    node and variable names prefixed with the graph's name when there are several.
    """
    from graphflow.usd.errors import StageError
    from graphflow.usd.physics_import import open_stage

    registry = registry or default_registry()
    label = str(stage_path)
    try:   # the same reading and messages as `graphflow stage` (file:line:column of a syntax error)
        stage, _ = open_stage(stage_path)
    except StageError as error:
        raise ImportProblem(error.problems) from None
    graphs = find_graphs(stage)
    if graph_path is None:
        if not graphs:
            raise ImportProblem([f"{label}: no OmniGraph prim in this stage"])
        selected = graphs
    else:
        graph_prim = stage.GetPrimAtPath(graph_path)
        if not graph_prim or graph_prim.GetTypeName() != GRAPH_TYPE:
            raise ImportProblem([f"{label}: {graph_path} is not an OmniGraph prim (graphs here: {', '.join(graphs) or 'none'})"])
        selected = [graph_path]

    warnings: list[str] = []
    problems: list[str] = []
    runs = [(path, target) for path in selected
            for target in graph_targets(stage, stage.GetPrimAtPath(path), label, _value, warnings)]
    keys = [path if target == path else target for path, target in runs]    # an instance is named by its target
    prefixes = graph_prefixes(keys) if len(keys) > 1 else {key: "" for key in keys}
    merged: dict = {"nodes": [], "connections": [], "ui": {}, "variables": [], "missingAssets": []}
    parts: dict = {}
    for (path, target), key in zip(runs, keys):
        if path not in parts:
            parts[path] = _import_one(stage, stage.GetPrimAtPath(path), label, registry, skip_unknown, warnings,
                                      problems)
        for name, value in prefixed(bind_target(parts[path], target), prefixes[key]).items():
            merged[name].update(value) if name == "ui" else merged[name].extend(value)
    if problems:
        raise ImportProblem(problems)

    settings = {"evaluator": "execution", "stage": _stage_reference(stage_path, output_path)}
    if merged["missingAssets"]:
        settings["missingAssets"] = merged["missingAssets"]
    data = {"format": FORMAT_NAME, "formatVersion": list(FORMAT_VERSION),
            "description": f"Imported from {Path(stage_path).name}:{', '.join(selected)}",
            "settings": settings, "nodes": merged["nodes"], "connections": merged["connections"]}
    if merged["variables"]:
        data["variables"] = merged["variables"]
    if merged["ui"]:
        data["ui"] = {"nodes": merged["ui"]}
    try:
        document = parse_document(data, source=output_path or f"{label}:{', '.join(selected)}", registry=registry)
    except GraphError as error:   # name the .usda the values came from, not the graph file not yet written
        raise ImportProblem([str(replace(problem, file=label)) for problem in error.problems]) from None
    return ImportResult(document, ", ".join(selected), warnings)


def _import_one(stage, graph_prim, label: str, registry: Registry, skip_unknown: bool,
                warnings: list[str], problems: list[str]) -> dict:
    """One OmniGraph prim as unprefixed document parts (nodes, connections, ui, variables, missing assets)."""
    graph_path = str(graph_prim.GetPath())
    evaluator = _value(graph_prim.GetAttribute("evaluator:type"))
    if evaluator not in (None, "execution"):
        warnings.append(f"{label}: {graph_path}: evaluator {evaluator!r} imported as an action graph (execution)")

    node_prims = [child for child in graph_prim.GetChildren() if child.GetTypeName() == NODE_TYPE]
    nodes, kept, ui, renames, extra_connections, missing_assets = [], {}, {}, {}, [], []
    for prim in node_prims:
        name, type_id = prim.GetName(), _value(prim.GetAttribute("node:type"))
        version = _value(prim.GetAttribute("node:typeVersion"))
        if type_id in RENDERING_NODES:
            warnings.append(f"{label}: node '{name}' ({type_id}): dropped: {RENDERING_NODES[type_id]} ({prim.GetPath()})")
            continue
        legacy_gripper = is_legacy_surface_gripper(type_id, version)
        if legacy_gripper:
            type_id, version = LEGACY_GRIPPER_ID, None
        node_type = registry.get(type_id) if type_id else None
        if node_type is None:
            message = f"{label}: node '{name}' ({prim.GetPath()}): unknown node type {type_id!r}"
            hint = registry.suggest(type_id or "")
            message += f" (did you mean {hint!r}?)" if hint else ""
            if skip_unknown:
                warnings.append(message + "; skipped")
            else:
                problems.append(message)
            continue
        authored_version = int(version) if version is not None else None
        era = era_of(type_id, _ports(prim), f"{label}: node '{name}'", warnings)
        if era is not None:   # the node an older omni.graph.nodes hosted under this id (node_eras)
            node_type, type_id = registry.get(era.now), era.now
            assert node_type is not None, era.now   # ERAS names implemented types (tests/usd/test_node_eras.py)
            version = node_type.spec.version
            renames.update({(name, old): (f"{name}.{new}" if new else None) for old, new in era.renames.items()})
        kept[name] = node_type
        if version is not None and _version_mapped(node_type.spec, int(version)):
            changes = map_version(node_type.spec, int(version), _ports(prim), f"{label}: node '{name}'", warnings)
            renames.update({(name, old): (f"{name}.{new}" if new else None) for old, new in changes.items()})
            version = node_type.spec.version
        inputs = _mapped_inputs(prim, node_type, label, warnings, problems, renames)
        inputs = upgraded_values(type_id, authored_version, era_inputs(era, inputs) if era else inputs,
                                 f"{label}: node '{name}'", warnings)
        if node_type.spec.id in NODE_PATH_READERS and str(inputs.get("path", "")).startswith(graph_path + "/"):
            inputs["path"] = inputs["path"][len(graph_path) + 1:]   # a node of this graph: by its name
        if legacy_gripper and any(prim.GetAttribute(pin).GetConnections() for pin in LEGACY_GRIPPER_COMMANDS):
            command, link = legacy_gripper_command_node(name, f"{label}: node '{name}'", warnings)
            nodes.append(command)
            extra_connections.append(link)
        for attribute, paths in _prim_inputs(node_type.spec, inputs):
            if paths:
                for target in paths:
                    if INSTANCE_TOKEN in target:
                        continue      # bound to each instance's target prim later (bind_target)
                    missing = missing_target(stage, target)
                    if missing:
                        warnings.append(f"{label}: node '{name}' input 'inputs:{attribute.name}': {missing[0]}")
                        if missing[1]:   # kept: only the computes that need the prim fail
                            missing_assets.append({"node": name, "input": f"inputs:{attribute.name}",
                                                   "message": missing[0]})
        entry = {"name": name, "type": type_id, "inputs": inputs}
        if version is not None:   # ports were mapped to graphflow's version above: the file is written at it
            entry["typeVersion"] = node_type.spec.version if node_type is not None else int(version)
        if not entry["inputs"]:
            del entry["inputs"]
        nodes.append(entry)
        position = _value(prim.GetAttribute(UI_POSITION))
        if position is not None:
            ui[name] = {"pos": [round(float(c), 3) for c in position]}
    bundle_nodes, bundle_connections, bundle_renames = expand(node_prims, kept, registry, _value, label, warnings)
    nodes += bundle_nodes
    renames.update(bundle_renames)
    connections = (_connections(node_prims, graph_prim.GetPath(), kept, label, warnings, renames, registry,
                                nodes) + extra_connections + bundle_connections)
    return {"nodes": nodes, "connections": connections, "ui": ui, "missingAssets": missing_assets,
            "variables": graph_variables(graph_prim, label, _value, warnings)}


def _version_mapped(spec, version: int) -> bool:
    """Whether a node authored at *version* needs mapping: a version graphflow lacks, or one whose ports moved."""
    return not spec.accepts_version(version) or (version != spec.version and (spec.id, version) in PORT_CHANGES)


def _ports(prim) -> set[str]:
    """The node prim's inputs and outputs that carry a value or a connection (what a version change can break)."""
    return {prop.GetName() for prop in prim.GetAuthoredProperties()
            if prop.GetName().startswith(("inputs:", "outputs:")) and _has_content(prop)}


def _stage_reference(stage_path: str, output_path: str | None) -> str:
    base = Path(output_path).resolve().parent if output_path else Path.cwd()
    return Path(os.path.relpath(Path(stage_path).resolve(), base)).as_posix()


def _authored_inputs(prim, node_type, label: str, warnings: list[str], removed: frozenset | set = frozenset(),
                     moved: dict | None = None) -> dict:
    """Authored values of graphflow's inputs; others dropped with a line (*removed*: already named by a version map,
    *moved*: inputs a version map renamed, old -> new)."""
    spec = node_type.spec
    inputs = {}
    for prop in prim.GetAuthoredProperties():
        name = prop.GetName()
        if not name.startswith("inputs:") or name in removed:
            continue
        name = (moved or {}).get(name, name)
        attribute = spec.attribute(name)
        if attribute is None:
            if _has_content(prop):
                warnings.append(f"{label}: node '{prim.GetName()}' input '{name}': not an input of graphflow's {spec.id}; dropped")
            continue
        if attribute.is_execution or attribute.attr_type.is_bundle:   # set by connections (bundle_ports)
            continue
        if hasattr(prop, "GetTargets"):  # a relationship: target inputs hold prim paths
            targets = [str(path) for path in prop.GetTargets()]
            if targets:
                inputs[attribute.name] = targets
            continue
        value = _value(prop)
        stored = _plain(prop.GetCustomDataByKey(EXTENDED_VALUE))
        if stored is not None and value in (None, ""):
            # Kit stores extended ("any") inputs as a token plus the resolved value in customData, and reads that
            # value when the token is empty (a sublayer may author "" over it)
            value = stored
        if value is not None and not prop.HasAuthoredConnections():
            inputs[attribute.name] = value
    return inputs


def _mapped_inputs(prim, node_type, label: str, warnings: list[str], problems: list[str], renames: dict) -> dict:
    """Authored inputs for graphflow's node, with older node versions and dynamic inputs mapped (node_mapping)."""
    name, spec = prim.GetName(), node_type.spec
    where = f"{label}: node '{name}'"
    if spec.id == LEGACY_GRIPPER_ID and _value(prim.GetAttribute("node:type")) != LEGACY_GRIPPER_ID:
        renames.update(legacy_gripper_renames(name))
        return map_legacy_surface_gripper(name, _raw_inputs(prim), where, warnings)
    if spec.id == PICK_PLACE_ID:
        raw = _raw_inputs(prim)
        old = {key: value for key, value in raw.items() if key in PICK_PLACE_OLD_INPUTS}
        current = _authored_inputs(prim, node_type, label, [])
        return {**current, **map_old_pick_place(old, where, warnings, problems)} if old else current
    if spec.id in DYNAMIC_INPUTS:     # its dynamic inputs become InsertAttribute nodes (bundle_ports), named there
        return _authored_inputs(prim, node_type, label, [])
    if spec.id in GENERIC_PUBLISHERS:
        fields = {key: value for key, value in _raw_inputs(prim).items() if spec.attribute(f"inputs:{key}") is None}
        for key in fields:
            renames[(name, f"inputs:{key}")] = None   # a field attribute has no port to connect to
        inputs = _authored_inputs(prim, node_type, label, [])
        if fields:
            inputs["messageFields"] = gather_message_fields(fields, where, warnings)
        return inputs
    removed = {port for (node, port), new in renames.items() if node == name and new is None}
    moved = {port: new.split(".", 1)[1] for (node, port), new in renames.items() if node == name and new}
    return _authored_inputs(prim, node_type, label, warnings, removed, moved)


def _raw_inputs(prim) -> dict:
    """Every authored, unconnected input with content, by bare name (relationships as lists of paths)."""
    values = {}
    for prop in prim.GetAuthoredProperties():
        if not prop.GetName().startswith("inputs:"):
            continue
        key = prop.GetName().split(":", 1)[1]
        if hasattr(prop, "GetTargets"):
            if prop.GetTargets():
                values[key] = [str(path) for path in prop.GetTargets()]
            continue
        value = _value(prop)
        if value is not None and not prop.HasAuthoredConnections():
            values[key] = value
    return values


def _has_content(prop) -> bool:
    if hasattr(prop, "GetTargets"):
        return bool(prop.GetTargets())
    return prop.HasAuthoredValue() or prop.HasAuthoredConnections() or prop.GetCustomDataByKey(EXTENDED_VALUE) is not None


def _connections(node_prims, graph_path, kept: dict, label: str, warnings: list[str], renames: dict,
                 registry: Registry, nodes: list[dict]) -> list[dict]:
    """The graph's connections; a generic subscriber's per-field output gets a ROS2MessageField node in *nodes*."""
    connections: list[dict] = []
    for prim in node_prims:
        if prim.GetName() not in kept:
            continue
        for name, sources in input_sources(prim, kept[prim.GetName()].spec):
            for source in sources:
                source_node = source.GetPrimPath()
                source_name = source.name
                where = f"{label}: node '{prim.GetName()}' input '{name}'"
                if source_node.GetParentPath() != graph_path:
                    warnings.append(f"{where}: connection from {source} outside the graph; dropped")
                    continue
                if source_node.name not in kept:
                    warnings.append(f"{where}: connection from {source} (no such imported node); dropped")
                    continue
                destination = renames.get((prim.GetName(), name), f"{prim.GetName()}.{name}")
                if destination is None:
                    warnings.append(f"{where}: connection from {source} has no equivalent input in graphflow's node; dropped")
                    continue
                if source_name.startswith("inputs:"):
                    # Kit lets constants be read from their input; graphflow's constants expose it as an output
                    source_name = "outputs:" + source_name.split(":", 1)[1]
                source_name = renames.get((source_node.name, source_name), f"{source_node.name}.{source_name}")
                if source_name and _missing_port(kept, source_name) and not _missing_port(kept, _underscored(source_name)):
                    source_name = _underscored(source_name)   # Kit's outputs:primvars:st is primvars_st here
                if source_name and kept[source_node.name].spec.id in GENERIC_SUBSCRIBERS and \
                        _missing_port(kept, source_name):
                    source_name = message_field(source_node.name, source.name, kept, registry, nodes, connections,
                                                f"{label}: node '{source_node.name}'", warnings)
                gone = ("its source port was removed in this version" if source_name is None
                        else _missing_port(kept, source_name) or _missing_port(kept, destination))
                if gone:
                    warnings.append(f"{where}: connection from {source} dropped: {gone}")
                    continue
                connections.append({"src": source_name, "dst": destination})
    return connections


def _underscored(endpoint: str) -> str:
    """``node.outputs:primvars:st`` as ``node.outputs:primvars_st``: a Kit port name with colons, as its node declares it."""
    node, group, name = endpoint.split(".", 1)[0], *endpoint.split(".", 1)[1].split(":", 1)
    return f"{node}.{group}:{name.replace(':', '_')}"


def _missing_port(kept: dict, endpoint: str | None) -> str | None:
    """``ID PORT`` when *endpoint* (``node.port``) names a port its imported node's type does not have."""
    if endpoint is None:
        return None
    node, port = endpoint.split(".", 1)
    node_type = kept.get(node)
    if node_type is None or node_type.spec.attribute(port) is not None:
        return None
    return f"graphflow's {node_type.spec.id} has no port '{port}'"


def _prim_inputs(spec, inputs: dict):
    """(attribute, prim paths) of each input naming prims: targets, and the path tokens (robotPath, primPath...)
    a node reads when its usePath is on (or it has none)."""
    use_path = inputs.get("usePath", spec.attribute("inputs:usePath").default
                          if spec.attribute("inputs:usePath") else True)
    for attribute in spec.inputs:
        value = inputs.get(attribute.name)
        if attribute.attr_type.base == "target":
            yield attribute, tuple(value or ())
        elif (attribute.attr_type.base in ("token", "string", "path") and not attribute.attr_type.is_array
              and attribute.name.endswith("Path") and use_path and isinstance(value, str)
              and value.startswith("/") and "." not in value.rsplit("/", 1)[-1]):
            yield attribute, (value,)


def _value(attribute):
    """An attribute's composed value as plain JSON-ready Python (None when unset)."""
    if not attribute or not attribute.HasAuthoredValue():
        return None
    return _plain(attribute.Get())


def _plain(value):
    if isinstance(value, float) and not math.isfinite(value):   # graph files are strict JSON: "nan", "inf", "-inf"
        return "nan" if math.isnan(value) else ("inf" if value > 0 else "-inf")
    if value is None or isinstance(value, (bool, int, float, str)):
        return value
    if hasattr(value, "pathString"):
        return value.pathString
    if hasattr(value, "imaginary") and hasattr(value, "real"):  # Gf.Quat*: graphflow stores x, y, z, w
        return [*(float(c) for c in value.imaginary), float(value.real)]
    if type(value).__name__ == "TimeCode":  # Sdf.TimeCode: its number of time codes
        return float(value.GetValue())
    if hasattr(value, "GetRow"):  # Gf.Matrix*: graphflow stores matrices flat, row by row
        return [float(c) for row in value for c in row]
    try:
        return [_plain(item) for item in value]
    except TypeError:
        return str(value)
