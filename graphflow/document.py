"""Graph documents: the JSON file format, its validation, and atomic saving.

A ``GraphDocument`` is immutable and holds authored values exactly as written,
so load -> save -> load is byte-identical. Validation reports every problem of
a file at once, each as one line naming the file, node and attribute.
"""
from __future__ import annotations

import json
import math
import os
from dataclasses import dataclass, field, replace
from functools import lru_cache
from importlib import resources
from pathlib import Path
from types import MappingProxyType
from typing import Any, Mapping

import networkx as nx

from .files import FileProblem, one_line, read_json, write_text
from .registry import Registry, default_registry
from .spec import NodeType
from .types import TypeMismatch, can_connect, parse_type

FORMAT_NAME = "graphflow"
FORMAT_VERSION = (1, 0)
MAX_DURATION = 1e7      # simulated seconds (116 days): longer is a typo, not a run (also the CLI's --seconds limit)
MAX_HINTED_TYPES = 50   # unknown node types per file that get a "did you mean" hint


@dataclass(frozen=True)
class Problem:
    """One thing wrong with a graph file."""

    file: str
    message: str
    node: str | None = None
    attribute: str | None = None
    kind: str = "input"  # how the attribute is named in the message: input, output, connection, variable
    path: tuple = ()     # where in the JSON a schema problem is (("nodes", 3, "name")); () for the others

    def __str__(self) -> str:
        locator = []
        if self.node is not None:
            locator.append(f"node '{self.node}'")
        if self.attribute is not None:
            locator.append(f"{self.kind} '{self.attribute}'")
        if locator:
            return one_line(f"{self.file}: {' '.join(locator)}: {self.message}")
        return one_line(f"{self.file}: {self.message}")


class GraphError(ValueError):
    """A graph file could not be loaded; ``problems`` lists every reason."""

    def __init__(self, problems: list[Problem]):
        self.problems = problems
        super().__init__("\n".join(str(p) for p in problems))


def _frozen(mapping: Mapping) -> Mapping:
    return MappingProxyType(dict(mapping))


@dataclass(frozen=True)
class NodeDoc:
    name: str
    type: str
    type_version: int | None = None
    inputs: Mapping[str, Any] = field(default_factory=dict)
    description: str = ""


@dataclass(frozen=True)
class Connection:
    src_node: str
    src_attr: str   # "outputs:x"
    dst_node: str
    dst_attr: str   # "inputs:y"

    @property
    def src(self) -> str:
        return f"{self.src_node}.{self.src_attr}"

    @property
    def dst(self) -> str:
        return f"{self.dst_node}.{self.dst_attr}"


@dataclass(frozen=True)
class Variable:
    name: str
    type: str
    default: Any = None
    description: str = ""


@dataclass(frozen=True)
class GraphDocument:
    """A graph as authored; no runtime state."""

    nodes: tuple[NodeDoc, ...]
    connections: tuple[Connection, ...] = ()
    variables: tuple[Variable, ...] = ()
    settings: Mapping[str, Any] = field(default_factory=dict)
    description: str = ""
    ui: Mapping[str, Any] = field(default_factory=dict)
    format_version: tuple[int, int] = FORMAT_VERSION
    source: str = "<graph>"   # the file it came from, for messages and relative stage paths

    def node(self, name: str) -> NodeDoc | None:
        return next((n for n in self.nodes if n.name == name), None)

    @property
    def base_dir(self) -> Path:
        return Path(self.source).resolve().parent if self.source != "<graph>" else Path.cwd()

    def to_json(self) -> dict:
        data: dict[str, Any] = {"format": FORMAT_NAME, "formatVersion": list(self.format_version)}
        if self.description:
            data["description"] = self.description
        if self.settings:
            data["settings"] = dict(self.settings)
        if self.variables:
            data["variables"] = [_variable_json(v) for v in self.variables]
        data["nodes"] = [_node_json(n) for n in self.nodes]
        if self.connections:
            data["connections"] = [{"src": c.src, "dst": c.dst} for c in self.connections]
        if self.ui:
            data["ui"] = dict(self.ui)
        return data


def _node_json(node: NodeDoc) -> dict:
    entry: dict[str, Any] = {"name": node.name, "type": node.type}
    if node.type_version is not None:
        entry["typeVersion"] = node.type_version
    if node.inputs:
        entry["inputs"] = dict(node.inputs)
    if node.description:
        entry["description"] = node.description
    return entry


def _variable_json(variable: Variable) -> dict:
    entry: dict[str, Any] = {"name": variable.name, "type": variable.type}
    if variable.default is not None:
        entry["default"] = variable.default
    if variable.description:
        entry["description"] = variable.description
    return entry


@lru_cache(maxsize=1)
def json_schema() -> dict:
    """The published JSON Schema of the graph format (also shipped as graphflow/schema/graph.schema.json)."""
    text = resources.files("graphflow").joinpath("schema/graph.schema.json").read_text(encoding="utf-8")
    return json.loads(text)


def _schema_problems(data: Any, source: str) -> list[Problem]:
    import jsonschema

    validator = jsonschema.Draft202012Validator(json_schema())
    problems = []
    for error in sorted(validator.iter_errors(data), key=lambda e: [str(p) for p in e.absolute_path]):
        path = error.absolute_path
        node_name = None
        if len(path) >= 2 and path[0] == "nodes" and isinstance(data, dict):
            try:
                node_name = data["nodes"][path[1]].get("name")
            except (IndexError, AttributeError, KeyError, TypeError):
                node_name = None
        location = "/".join(str(p) for p in path) or "document"
        message = error.message
        if error.validator == "pattern" and path and path[-1] == "name":
            message = f"{error.instance!r} is not a name (letters, digits, '_' and '-', not starting with a digit or '-')"
        if not isinstance(node_name, str):
            node_name = None
        problems.append(Problem(source, f"{location}: {message}", node=node_name, path=tuple(path)))
    return problems


def parse_document(data: Any, source: str = "<graph>", registry: Registry | None = None) -> GraphDocument:
    """Build and validate a document from parsed JSON; raise GraphError listing every problem."""
    problems = _schema_problems(data, source)
    if problems:
        raise GraphError(problems + _problems_of_valid_parts(data, source, registry, problems))
    major = data["formatVersion"][0]
    if major != FORMAT_VERSION[0]:
        raise GraphError([Problem(source, f"formatVersion {data['formatVersion']} is not supported (this runtime reads {FORMAT_VERSION[0]}.x)")])
    document = GraphDocument(
        nodes=tuple(NodeDoc(n["name"], n["type"], n.get("typeVersion"), _frozen(n.get("inputs", {})),
                            n.get("description", "")) for n in data["nodes"]),
        connections=tuple(_parse_connection(c) for c in data.get("connections", [])),
        variables=tuple(Variable(v["name"], v["type"], v.get("default"), v.get("description", ""))
                        for v in data.get("variables", [])),
        settings=_frozen(data.get("settings", {})),
        description=data.get("description", ""),
        ui=_frozen(data.get("ui", {})),
        format_version=tuple(data["formatVersion"]),
        source=source,
    )
    problems = validate(document, registry)
    if problems:
        raise GraphError(problems)
    return document


def _problems_of_valid_parts(data: Any, source: str, registry: Registry | None, schema_problems) -> list[Problem]:
    """Semantic problems of the entries the schema accepted, so one pass lists both kinds."""
    if not isinstance(data, dict) or not isinstance(data.get("nodes"), list):
        return []
    broken = {tuple(p.path[:2]) for p in schema_problems if len(p.path) >= 2}
    broken_sections = {p.path[0] for p in schema_problems if len(p.path) == 1}

    def kept(section: str) -> list:
        entries = data.get(section, [])
        if section in broken_sections or not isinstance(entries, list):
            return []
        return [entry for index, entry in enumerate(entries) if (section, index) not in broken]

    skipped = {entry.get("name") for index, entry in enumerate(data["nodes"])
               if ("nodes", index) in broken and isinstance(entry, dict)}
    settings = data.get("settings", {})
    document = GraphDocument(
        nodes=tuple(NodeDoc(n["name"], n["type"], n.get("typeVersion"), _frozen(n.get("inputs", {})))
                    for n in kept("nodes")),
        connections=tuple(_parse_connection(c) for c in kept("connections")),
        variables=tuple(Variable(v["name"], v["type"], v.get("default")) for v in kept("variables")),
        settings=_frozen(settings if isinstance(settings, dict) and "settings" not in broken_sections
                         and not any(p.path[:1] == ("settings",) for p in schema_problems) else {}),
        source=source)
    return [problem for problem in validate(document, registry) if problem.node not in skipped]


def _parse_connection(entry: dict) -> Connection:
    src_node, src_attr = entry["src"].split(".", 1)
    dst_node, dst_attr = entry["dst"].split(".", 1)
    return Connection(src_node, src_attr, dst_node, dst_attr)


def load_document(path: str | os.PathLike, registry: Registry | None = None) -> GraphDocument:
    """Read (strict JSON: see graphflow.files) and validate a graph file."""
    try:
        data = read_json(path)
    except FileProblem as error:
        raise GraphError([Problem(str(path), error.reason)]) from None
    return parse_document(data, str(path), registry)


def dumps(document: GraphDocument) -> str:
    """The canonical text of a document: pretty-printed, sorted keys, trailing newline."""
    return json.dumps(document.to_json(), indent=2, sort_keys=True, ensure_ascii=False) + "\n"


def save_document(document: GraphDocument, path: str | os.PathLike, *, force: bool = True) -> None:
    """Write atomically (graphflow.files.write_text): never half-written, over an existing file only with *force*.

    A relative ``settings.stage`` is rebased onto the new file's folder, so the saved graph still finds its stage.
    """
    write_text(path, dumps(rebased(document, path)), force=force)


def rebased(document: GraphDocument, path: str | os.PathLike) -> GraphDocument:
    """*document* as it must read when saved at *path*: its relative stage path made relative to that folder."""
    stage = document.settings.get("stage")
    if not isinstance(stage, str) or stage.startswith("asset:") or Path(stage).is_absolute():
        return document
    folder = Path(path).resolve().parent
    if folder == document.base_dir:
        return document
    moved = Path(os.path.relpath(document.base_dir / stage, folder)).as_posix()
    return replace(document, settings=_frozen({**document.settings, "stage": moved}), source=str(path))


# ---------------------------------------------------------------- validation

def validate(document: GraphDocument, registry: Registry | None = None) -> list[Problem]:
    """Every semantic problem of a document (the schema was already checked)."""
    registry = registry or default_registry()
    source = document.source
    problems: list[Problem] = []
    types: dict[str, NodeType] = {}

    seen: set[str] = set()
    unknown: set[str] = set()
    for node in document.nodes:
        if node.name in seen:
            problems.append(Problem(source, "duplicate node name", node=node.name))
        seen.add(node.name)
        node_type = registry.get(node.type)
        if node_type is None:
            unknown.add(node.type)   # hints for the first few dozen unknown types: the search costs ~1 ms each
            hint = registry.suggest(node.type) if len(unknown) <= MAX_HINTED_TYPES else None
            problems.append(Problem(source, f"unknown node type {node.type!r}" + (f" (did you mean {hint!r}?)" if hint else ""), node=node.name))
            continue
        types[node.name] = node_type
        problems.extend(_node_problems(source, node, node_type))

    problems.extend(_settings_problems(source, document.settings))
    problems.extend(_variable_problems(source, document.variables))
    problems.extend(_connection_problems(source, document, types))
    return problems


def _node_problems(source: str, node: NodeDoc, node_type: NodeType) -> list[Problem]:
    spec = node_type.spec
    problems = []
    if node.type_version is not None and not spec.accepts_version(node.type_version):
        problems.append(Problem(source, f"typeVersion {node.type_version} of {spec.id} is not supported (this runtime has version {spec.version})", node=node.name))
    for name, value in node.inputs.items():
        qualified = f"inputs:{name}"
        attribute = spec.attribute(qualified)
        if attribute is None:
            problems.append(Problem(source, f"{spec.id} has no such input", node=node.name, attribute=qualified))
            continue
        if attribute.is_execution:
            problems.append(Problem(source, "execution inputs take connections, not values", node=node.name, attribute=qualified))
            continue
        try:
            attribute.check(value)
        except TypeMismatch as error:
            problems.append(Problem(source, str(error), node=node.name, attribute=qualified))
    if node_type.validate is not None and not problems:
        for message in node_type.validate(node.name, dict(node.inputs)):
            problems.append(Problem(source, message, node=node.name))
    return problems


def _settings_problems(source: str, settings: Mapping[str, Any]) -> list[Problem]:
    """Numbers the schema lets through but a run cannot use (NaN and infinity pass its range checks,
    and a duration of 1e308 s would never end)."""
    problems = [Problem(source, f"settings/{name}: {value!r} is not a finite number")
                for name in ("timeStep", "duration", "substeps", "stepBudget")
                if isinstance(value := settings.get(name), float) and not math.isfinite(value)]
    duration = settings.get("duration")
    if isinstance(duration, (int, float)) and math.isfinite(duration) and duration > MAX_DURATION:
        problems.append(Problem(source, f"settings/duration: {duration!r} s is more than {MAX_DURATION:g} simulated seconds"))
    return problems


def _variable_problems(source: str, variables) -> list[Problem]:
    problems, seen = [], set()
    for variable in variables:
        if variable.name in seen:
            problems.append(Problem(source, "duplicate variable name", attribute=variable.name, kind="variable"))
        seen.add(variable.name)
        try:
            attr_type = parse_type(variable.type)
        except ValueError as error:
            problems.append(Problem(source, str(error), attribute=variable.name, kind="variable"))
            continue
        if attr_type.is_execution:
            problems.append(Problem(source, "a variable cannot be of execution type (exec pulses are not values)",
                                    attribute=variable.name, kind="variable"))
            continue
        if variable.default is not None:
            try:
                attr_type.coerce(variable.default)
            except TypeMismatch as error:
                problems.append(Problem(source, f"default: {error}", attribute=variable.name, kind="variable"))
    return problems


def _connection_problems(source: str, document: GraphDocument, types: dict[str, NodeType]) -> list[Problem]:
    problems = []
    names = {n.name for n in document.nodes}
    data_sources: dict[tuple[str, str], list[str]] = {}
    data_graph = nx.DiGraph()
    for connection in document.connections:
        label = f"{connection.src} -> {connection.dst}"
        endpoints = []
        for node_name, attr_name in ((connection.src_node, connection.src_attr), (connection.dst_node, connection.dst_attr)):
            if node_name not in names:
                problems.append(Problem(source, f"dangling connection {label}: no node named '{node_name}'", node=node_name, attribute=attr_name, kind="connection"))
                endpoints.append(None)
                continue
            node_type = types.get(node_name)
            if node_type is None:
                endpoints.append(None)  # the unknown type was already reported
                continue
            attribute = node_type.spec.attribute(attr_name)
            if attribute is None:
                problems.append(Problem(source, f"dangling connection {label}: {node_type.spec.id} has no attribute '{attr_name}'", node=node_name, attribute=attr_name, kind="connection"))
            endpoints.append(attribute)
        src_attribute, dst_attribute = endpoints
        if src_attribute is None or dst_attribute is None:
            continue
        if not can_connect(src_attribute.attr_type, dst_attribute.attr_type):
            problems.append(Problem(source, f"type mismatch in {label}: {src_attribute.type} cannot feed {dst_attribute.type}", node=connection.dst_node, attribute=connection.dst_attr, kind="connection"))
            continue
        if not dst_attribute.is_execution:
            data_sources.setdefault((connection.dst_node, connection.dst_attr), []).append(connection.src)
            data_graph.add_edge(connection.src_node, connection.dst_node)
    for (node_name, attr_name), sources in data_sources.items():
        if len(sources) > 1:
            problems.append(Problem(source, f"more than one source into a data input: {', '.join(sources)}", node=node_name, attribute=attr_name, kind="connection"))
    for cycle in _data_cycles(data_graph):
        problems.append(Problem(source, f"data cycle: {' -> '.join(cycle + [cycle[0]])}", node=cycle[0]))
    return problems


def _data_cycles(graph: nx.DiGraph) -> list[list[str]]:
    """One cycle per strongly connected component that loops (deterministic order)."""
    cycles = []
    for component in nx.strongly_connected_components(graph):
        members = sorted(component)
        if len(members) == 1 and not graph.has_edge(members[0], members[0]):
            continue
        cycle = nx.find_cycle(graph.subgraph(members), source=members[0])
        cycles.append([edge[0] for edge in cycle])
    return sorted(cycles)
