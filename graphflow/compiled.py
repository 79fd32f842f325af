"""A compiled graph: everything a tick needs, resolved once from a checked document (immutable).

Per node: its exec pin names, its exec fan-out as ready-made stack entries, and a *pull program*: the
pure nodes its data pulls depend on, in order, as one generated Python function of straight-line code
(``CompiledGraph.pull_source`` shows it). ``graphflow.compiler.compile`` is the only maker; the executor's
``GraphInstance`` binds a compiled graph to run-time values.
"""
from __future__ import annotations

import linecache
from dataclasses import dataclass
from typing import Any

import networkx as nx

from graphflow.model import GraphDocument
from graphflow.registry import Registry
from graphflow.spec import NodeSpec, NodeType

DEFAULT_STEP_BUDGET = 100_000   # most node computes in one tick before a run stops as a runaway loop

@dataclass(frozen=True)
class CompiledNode:
    index: int
    name: str
    node_type: NodeType
    authored: tuple[tuple[str, Any], ...]          # coerced authored input values
    pulls: tuple[tuple[str, int, str], ...]        # (input name, source node index, source output name)
    pure_schedule: tuple[int, ...]                 # pure upstream nodes in topological order (exec nodes; () for pure)
    exec_targets: tuple[tuple[str, tuple[tuple[int, str], ...]], ...]  # per exec output: (dst index, dst exec input)

    @property
    def spec(self) -> NodeSpec:
        return self.node_type.spec


class CompiledGraph:
    """Immutable evaluation tables of a document whose checks passed.

    Made only by ``graphflow.compiler.compile``, which checks the document and hands over what it
    resolved: node types, coerced authored inputs, the valid connections as per-node pulls and exec
    fan-out, the data graph over node indices, and the variables' types and initial values.
    """

    def __init__(self, document: GraphDocument, registry: Registry, *, node_types: tuple[NodeType, ...],
                 authored: tuple[tuple[tuple[str, Any], ...], ...], pulls: list[list[tuple[str, int, str]]],
                 exec_edges: list[dict[str, list[tuple[int, str]]]], data_graph: nx.DiGraph,
                 variable_types: dict, variable_defaults: dict):
        self.document = document
        self.registry = registry
        pure = [t.spec.is_pure for t in node_types]
        self.is_pure = tuple(pure)
        self._data_graph = data_graph   # for the schedules of pure nodes computed on their own (compute_node)
        self.nodes: tuple[CompiledNode, ...] = tuple(
            CompiledNode(
                index=i,
                name=node.name,
                node_type=node_types[i],
                authored=authored[i],
                pulls=tuple(pulls[i]),
                pure_schedule=() if pure[i] else _pure_schedule(data_graph, i, pure),
                exec_targets=tuple((a.name, tuple(exec_edges[i].get(a.name, ()))) for a in node_types[i].spec.exec_outputs),
            )
            for i, node in enumerate(document.nodes)
        )
        self.event_sources = tuple(n.index for n in self.nodes
                                   if n.spec.is_event_source and not n.spec.fires_at_run_end)
        self.run_end_sources = tuple(n.index for n in self.nodes if n.spec.fires_at_run_end)
        self.exec_input_names = tuple(tuple(a.name for a in n.spec.exec_inputs) for n in self.nodes)
        self.exec_output_names = tuple(tuple(a.name for a in n.spec.exec_outputs) for n in self.nodes)
        # exec stack entries are (node index, enabled exec input names): () for an event source or a re-entry
        self.plain_entries = tuple((i, ()) for i in range(len(self.nodes)))
        # per node, its exec outputs last to first, each with its targets last to first as stack entries:
        # pushing in this order pops the first output's first target first (LIFO stack, connection order)
        self.push_plans = tuple(
            tuple((name, tuple((dst, (dst_name,)) for dst, dst_name in reversed(targets)))
                  for name, targets in reversed(n.exec_targets))
            for n in self.nodes)
        # exec nodes each pure node depends on (through other pure nodes): their computes invalidate it
        exec_ancestors = _exec_ancestors(data_graph, pure)
        self.pure_exec_dependencies = tuple(
            tuple(sorted(exec_ancestors[i])) if pure[i] else () for i in range(len(self.nodes)))
        self.index_of = {node.name: i for i, node in enumerate(document.nodes)}
        self.variable_types = variable_types
        self.variable_defaults = variable_defaults
        self.step_budget = int(document.settings.get("stepBudget", DEFAULT_STEP_BUDGET))
        # the names pull programs use for node i's input dict, output dict, compute and database
        self.program_names = tuple((f"in{i}", f"out{i}", f"compute{i}", f"db{i}") for i in range(len(self.nodes)))
        # pure nodes are computed by their consumers' programs; theirs are made only if asked (compute_node)
        self._pull_programs: dict[int, Any] = {
            node.index: self._pull_program(node) for node in self.nodes if not self.is_pure[node.index]}

    def pull_program(self, index: int):
        """The compiled pull program of node *index* (None when it pulls no pure node)."""
        if index not in self._pull_programs:
            self._pull_programs[index] = self._pull_program(self.nodes[index])
        return self._pull_programs[index]

    def pull_source(self, node_name: str) -> str:
        """The generated Python source of a node's pull program ('' when it pulls no pure node)."""
        return self._pull_program_source(self.nodes[self.index_of[node_name]])

    def _pull_program_source(self, node: CompiledNode) -> str:
        """``pull(tick_epoch, epoch)``: compute the stale pure nodes upstream of *node*, sources first.

        Straight-line code, one block per pure node: it is stale when it has not computed this tick
        (its stamp is older than the tick's first epoch) or an exec node it depends on computed after
        it; then it is stamped and counted, its inputs are copied from their sources, and it computes.
        Globals (bound per instance): ``in<i>``/``out<i>`` node i's input/output dicts, ``compute<i>``,
        ``db<i>``, the instance's ``stamps``, ``last`` (epoch of each exec node's latest compute) and
        ``counts`` lists, ``failure`` and ``GraphRuntimeError``. Only indices and repr() of names
        reach the source, so no text from a graph file can become code.
        """
        schedule = _pure_schedule(self._data_graph, node.index, list(self.is_pure)) if self.is_pure[node.index] \
            else node.pure_schedule
        if not schedule:
            return ""
        lines = [f"def pull(tick_epoch, epoch):  # pure nodes pulled by {node.name!r}", "    node = -1", "    try:"]
        for i in schedule:
            pure_node = self.nodes[i]
            stale = f"stamps[{i}] < tick_epoch" + "".join(
                f" or last[{j}] > stamps[{i}]" for j in self.pure_exec_dependencies[i])
            lines.append(f"        if {stale}:  # {pure_node.name!r}")
            lines.append(f"            node = {i}; stamps[{i}] = epoch; counts[{i}] += 1")
            lines.extend(f"            in{i}[{name!r}] = out{source}[{source_name!r}]"
                         for name, source, source_name in pure_node.pulls)
            lines.append(f"            compute{i}(db{i})")
        lines += ["    except GraphRuntimeError:", "        raise", "    except Exception as error:",
                  "        raise failure(node, error) from error", ""]
        return "\n".join(lines)

    def _pull_program(self, node: CompiledNode):
        source = self._pull_program_source(node)
        if not source:
            return None
        filename = f"<graphflow pulls of {node.name!r} in {self.document.source!r}>"
        # tracebacks show the generated lines (one entry per graph source and node: bounded, never stale for long)
        linecache.cache[filename] = (len(source), None, source.splitlines(True), filename)
        return compile(source, filename, "exec")

def _exec_ancestors(data_graph: nx.DiGraph, pure: list[bool]) -> dict[int, frozenset[int]]:
    """Per node, the exec nodes among its data ancestors (one pass in topological order, not a search per node)."""
    found: dict[int, frozenset[int]] = {}
    for index in nx.topological_sort(data_graph):
        ancestors: set[int] = set()
        for upstream in data_graph.predecessors(index):
            ancestors.update(found[upstream])
            if not pure[upstream]:
                ancestors.add(upstream)
        found[index] = frozenset(ancestors)
    return found


def _pure_schedule(data_graph: nx.DiGraph, index: int, pure: list[bool]) -> tuple[int, ...]:
    """Pure nodes upstream of *index* (reached through pure nodes only), sources first."""
    reached, frontier = set(), [index]
    while frontier:
        current = frontier.pop()
        for upstream in data_graph.predecessors(current):
            if pure[upstream] and upstream not in reached:
                reached.add(upstream)
                frontier.append(upstream)
    if not reached:
        return ()
    order = nx.lexicographical_topological_sort(data_graph.subgraph(reached))
    return tuple(order)
