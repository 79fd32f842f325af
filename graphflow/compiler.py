"""Compiling a graph document: one pass that checks it and builds its evaluation tables.

``compile(document, registry)`` resolves every node type once, checks and
coerces every authored value once, resolves every connection endpoint once
and looks for data cycles; it reports every problem at once (``GraphError``,
one line per problem naming file, node and attribute) and only a document
without problems becomes a ``CompiledGraph``, built from what the checks
resolved. So the executor never meets an unknown type, a dangling connection
or an unchecked value, and nothing is looked up twice.

Loading a file (``parse_document``) checks it by compiling it; the document
keeps its compiled graph per registry, so every ``Simulation`` of that
document shares that one immutable compiled graph (benchmarks/instances.py).
"""
from __future__ import annotations

import difflib
import math
from typing import Any, TypeGuard

import networkx as nx

from graphflow.compiled import CompiledGraph
from graphflow.model import GraphDocument, GraphError, NodeDoc, Problem
from graphflow.registry import Registry, default_registry
from graphflow.spec import NodeType
from graphflow.types import TypeMismatch, can_connect, parse_type

__all__ = ["compile", "problems", "GraphError", "Problem"]

MAX_DURATION = 1e7      # simulated seconds (116 days): longer is a typo, not a run (also the CLI's --seconds limit)
MAX_HINTED_TYPES = 50   # unknown node types per file that get a "did you mean" hint (the search costs ~1 ms each)


def compile(document: GraphDocument, registry: Registry | None = None) -> CompiledGraph:
    """The compiled graph of *document*; raise GraphError listing every problem of it.

    Compiled once per document and registry: later calls return the same object.
    """
    registry = registry or default_registry()
    compiled = document._compiled.get(id(registry))
    if compiled is None or compiled.registry is not registry:
        compiled = _Compilation(document, registry).run()
        document._compiled[id(registry)] = compiled   # it holds the registry: the id stays its own
    return compiled


def problems(document: GraphDocument, registry: Registry | None = None) -> list[Problem]:
    """Every problem compiling *document* finds, without building anything (for partial documents)."""
    compilation = _Compilation(document, registry or default_registry())
    node_types, _authored = compilation._nodes()
    compilation._settings()
    compilation._checks()
    compilation._variables()
    compilation._connections(node_types)
    return compilation.problems


class _Compilation:
    """The single pass: each check keeps what it resolved, and the tables are built from that."""

    def __init__(self, document: GraphDocument, registry: Registry):
        self.document = document
        self.registry = registry
        self.source = document.source
        self.problems: list[Problem] = []

    def run(self) -> CompiledGraph:
        document = self.document
        node_types, authored = self._nodes()
        self._settings()
        self._checks()
        variable_types, variable_defaults = self._variables()
        pulls, exec_edges, data_graph = self._connections(node_types)
        if self.problems:
            raise GraphError(self.problems)
        return CompiledGraph(document, self.registry, node_types=tuple(t for t in node_types if t is not None), authored=tuple(authored),
                             pulls=pulls, exec_edges=exec_edges, data_graph=data_graph,
                             variable_types=variable_types, variable_defaults=variable_defaults)

    def _problem(self, message: str, **where) -> None:
        self.problems.append(Problem(self.source, message, **where))

    # ---------------------------------------------------------------- nodes

    def _nodes(self) -> tuple[list[NodeType | None], list[tuple[tuple[str, Any], ...]]]:
        """Each node's type (None when unknown) and its authored inputs, coerced."""
        node_types: list[NodeType | None] = []
        authored: list[tuple[tuple[str, Any], ...]] = []
        seen: set[str] = set()
        unknown: set[str] = set()
        for node in self.document.nodes:
            if node.name in seen:
                self._problem("duplicate node name", node=node.name)
            seen.add(node.name)
            node_type = self.registry.get(node.type)
            node_types.append(node_type)
            if node_type is None:
                unknown.add(node.type)
                hint = self.registry.suggest(node.type) if len(unknown) <= MAX_HINTED_TYPES else None
                self._problem(f"unknown node type {node.type!r}" + (f" (did you mean {hint!r}?)" if hint else ""),
                              node=node.name)
                authored.append(())
                continue
            authored.append(self._authored_inputs(node, node_type))
        return node_types, authored

    def _authored_inputs(self, node: NodeDoc, node_type: NodeType) -> tuple[tuple[str, Any], ...]:
        spec = node_type.spec
        before = len(self.problems)
        if node.type_version is not None and not spec.accepts_version(node.type_version):
            self._problem(f"typeVersion {node.type_version} of {spec.id} is not supported "
                          f"(this runtime has version {spec.version})", node=node.name)
        values = []
        for name, value in node.inputs.items():
            qualified = f"inputs:{name}"
            attribute = spec.attribute(qualified)
            if attribute is None:
                close = difflib.get_close_matches(name, [a.name for a in spec.inputs], n=1)
                hint = f" (did you mean {close[0]!r}?)" if close else ""
                self._problem(f"{spec.id} has no such input{hint}", node=node.name, attribute=qualified)
                continue
            if attribute.is_execution:
                self._problem("execution inputs take connections, not values", node=node.name, attribute=qualified)
                continue
            try:
                values.append((name, attribute.check(value)))
            except TypeMismatch as error:
                self._problem(str(error), node=node.name, attribute=qualified)
        if node_type.validate is not None and len(self.problems) == before:
            for message in node_type.validate(node.name, dict(node.inputs)):
                self._problem(message, node=node.name)
        return tuple(values)

    # ---------------------------------------------------------------- settings

    def _settings(self) -> None:
        """Numbers the schema lets through but a run cannot use (NaN and infinity pass its range checks,
        and a duration of 1e308 s would never end)."""
        settings = self.document.settings
        for name in ("timeStep", "duration", "substeps", "stepBudget"):
            value = settings.get(name)
            if isinstance(value, float) and not math.isfinite(value):
                self._problem(f"settings/{name}: {value!r} is not a finite number")
        duration = settings.get("duration")
        if isinstance(duration, (int, float)) and math.isfinite(duration) and duration > MAX_DURATION:
            self._problem(f"settings/duration: {duration!r} s is more than {MAX_DURATION:g} simulated seconds")

    def _checks(self) -> None:
        """Check times a run cannot honour: a ``held`` window that ends before it starts, a time past
        ``settings.duration`` (the check would report a false failure after the whole run)."""
        duration = self.document.settings.get("duration")
        if not (isinstance(duration, (int, float)) and math.isfinite(duration)):
            duration = None
        for index, check in enumerate(self.document.checks, start=1):
            where = f"checks[{index}] ({check.get('check')}{', ' + repr(check['name']) if 'name' in check else ''})"
            start, end = check.get("from"), check.get("to")
            if _is_number(start) and _is_number(end) and start > end:
                self._problem(f"{where}: from {start:g} s is after to {end:g} s")
            for key in ("at", "from", "to", "time"):
                value = check.get(key)
                if not _is_number(value):
                    continue
                if not math.isfinite(value) or value < 0:
                    self._problem(f"{where}: {key} {value!r} is not a time in the run (a finite number >= 0)")
                elif duration is not None and value > duration:
                    self._problem(f"{where}: {key} {value:g} s is after the run ends "
                                  f"(settings/duration {duration:g} s)")

    # ---------------------------------------------------------------- variables

    def _variables(self) -> tuple[dict, dict]:
        """Each variable's type and initial value (its default coerced, or the type's default)."""
        types, defaults, seen = {}, {}, set()
        for variable in self.document.variables:
            if variable.name in seen:
                self._problem("duplicate variable name", attribute=variable.name, kind="variable")
            seen.add(variable.name)
            try:
                attr_type = parse_type(variable.type)
            except ValueError as error:
                self._problem(str(error), attribute=variable.name, kind="variable")
                continue
            if attr_type.is_execution:
                self._problem("a variable cannot be of execution type (exec pulses are not values)",
                              attribute=variable.name, kind="variable")
                continue
            try:
                value = attr_type.default_value() if variable.default is None else attr_type.coerce(variable.default)
            except TypeMismatch as error:
                self._problem(f"default: {error}", attribute=variable.name, kind="variable")
                continue
            types[variable.name], defaults[variable.name] = attr_type, value
        return types, defaults

    # ---------------------------------------------------------------- connections

    def _connections(self, node_types: list[NodeType | None]):
        """Per node its data pulls and exec fan-out, and the data graph (node indices), from valid connections."""
        document = self.document
        index_of = {node.name: i for i, node in enumerate(document.nodes)}
        pulls: list[list[tuple[str, int, str]]] = [[] for _ in document.nodes]
        exec_edges: list[dict[str, list[tuple[int, str]]]] = [{} for _ in document.nodes]
        data_graph = nx.DiGraph()
        data_graph.add_nodes_from(range(len(document.nodes)))
        data_sources: dict[tuple[str, str], list[str]] = {}
        for connection in document.connections:
            label = f"{connection.src} -> {connection.dst}"
            endpoints: list[Any] = []
            for node_name, attr_name in ((connection.src_node, connection.src_attr),
                                         (connection.dst_node, connection.dst_attr)):
                if node_name not in index_of:
                    self._problem(f"dangling connection {label}: no node named '{node_name}'",
                                  node=node_name, attribute=attr_name, kind="connection")
                    endpoints.append(None)
                    continue
                node_type = node_types[index_of[node_name]]
                if node_type is None:
                    endpoints.append(None)  # the unknown type was already reported
                    continue
                attribute = node_type.spec.attribute(attr_name)
                if attribute is None:
                    self._problem(f"dangling connection {label}: {node_type.spec.id} has no attribute '{attr_name}'",
                                  node=node_name, attribute=attr_name, kind="connection")
                endpoints.append(attribute)
            src_attribute, dst_attribute = endpoints
            if src_attribute is None or dst_attribute is None:
                continue
            if not can_connect(src_attribute.attr_type, dst_attribute.attr_type):
                self._problem(f"type mismatch in {label}: {src_attribute.type} cannot feed {dst_attribute.type}",
                              node=connection.dst_node, attribute=connection.dst_attr, kind="connection")
                continue
            src, dst = index_of[connection.src_node], index_of[connection.dst_node]
            if dst_attribute.is_execution:
                exec_edges[src].setdefault(src_attribute.name, []).append((dst, dst_attribute.name))
            else:
                data_sources.setdefault((connection.dst_node, connection.dst_attr), []).append(connection.src)
                pulls[dst].append((dst_attribute.name, src, src_attribute.name))
                data_graph.add_edge(src, dst)
        for (node_name, attr_name), sources in data_sources.items():
            if len(sources) > 1:
                self._problem(f"more than one source into a data input: {', '.join(sources)}",
                              node=node_name, attribute=attr_name, kind="connection")
        names = [node.name for node in document.nodes]
        for cycle in _data_cycles(data_graph, names):
            self._problem(f"data cycle: {' -> '.join(cycle + [cycle[0]])}", node=cycle[0])
        return pulls, exec_edges, data_graph


def _data_cycles(graph: nx.DiGraph, names: list[str]) -> list[list[str]]:
    """One cycle (as node names) per strongly connected component that loops, in a deterministic order.

    Each search starts at the component's alphabetically first node.
    """
    cycles = []
    for component in nx.strongly_connected_components(graph):
        if len(component) == 1:
            (only,) = component
            if not graph.has_edge(only, only):
                continue
        start = min(component, key=lambda index: names[index])
        cycle = nx.find_cycle(graph.subgraph(component), source=start)
        cycles.append([names[edge[0]] for edge in cycle])
    return sorted(cycles)


def _is_number(value: object) -> TypeGuard[float]:
    return isinstance(value, (int, float)) and not isinstance(value, bool)
