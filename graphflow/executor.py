"""The action-graph executor: exec push along an explicit stack, data pull with per-tick memoisation.

``CompiledGraph`` is built once from a validated document (immutable: ids,
connection tables, pull schedules). ``GraphInstance`` holds everything that
changes at run time, so ``reset()`` restores the initial state and one compiled
graph can be instanced many times side by side.
"""
from __future__ import annotations

import logging
from collections import Counter, deque
from dataclasses import dataclass
from typing import Any, Callable

import networkx as nx

from .document import GraphDocument
from .registry import Registry, default_registry
from .spec import NodeSpec, NodeType
from .types import ExecState, parse_type
from .world import ClockWorld, World

DEFAULT_STEP_BUDGET = 100_000
KEPT_LOG_EVENTS = 10_000   # the event log keeps the newest lines so long runs stay flat in memory
_REENTRY = "\0reentry"  # stack marker: compute the node again after its pushed downstream finished
log = logging.getLogger("graphflow.graph")

_DISABLED = ExecState.DISABLED
_ENABLED = ExecState.ENABLED
_ENABLED_AND_PUSH = ExecState.ENABLED_AND_PUSH
_LATENT_PUSH = ExecState.LATENT_PUSH
_LATENT_FINISH = ExecState.LATENT_FINISH


class GraphRuntimeError(RuntimeError):
    """A run-time failure naming the node (exit code 1 from the CLI)."""

    def __init__(self, message: str, node: str | None = None):
        self.node = node
        super().__init__(f"node '{node}': {message}" if node else message)


class StepBudgetExceeded(GraphRuntimeError):
    """More node computes in one tick than the budget allows: an exec loop that never ends."""


@dataclass(frozen=True)
class LogEvent:
    tick: int
    time: float
    node: str
    level: str
    message: str


@dataclass(frozen=True)
class CompiledNode:
    index: int
    name: str
    node_type: NodeType
    authored: tuple[tuple[str, Any], ...]          # coerced authored input values
    pulls: tuple[tuple[str, int, str], ...]        # (input name, source node index, source output name)
    pure_schedule: tuple[int, ...]                 # pure upstream nodes in topological order
    exec_targets: tuple[tuple[str, tuple[tuple[int, str], ...]], ...]  # per exec output: (dst index, dst exec input)

    @property
    def spec(self) -> NodeSpec:
        return self.node_type.spec


class CompiledGraph:
    """Immutable evaluation tables built from a document and a registry."""

    def __init__(self, document: GraphDocument, registry: Registry | None = None):
        registry = registry or default_registry()
        self.document = document
        index_of = {node.name: i for i, node in enumerate(document.nodes)}
        node_types = [registry.get(node.type) for node in document.nodes]
        pulls: list[list[tuple[str, int, str]]] = [[] for _ in document.nodes]
        exec_edges: list[dict[str, list[tuple[int, str]]]] = [{} for _ in document.nodes]
        data_graph = nx.DiGraph()
        data_graph.add_nodes_from(range(len(document.nodes)))
        for connection in document.connections:
            src, dst = index_of[connection.src_node], index_of[connection.dst_node]
            src_name, dst_name = connection.src_attr.split(":", 1)[1], connection.dst_attr.split(":", 1)[1]
            if node_types[dst].spec.attribute(connection.dst_attr).is_execution:
                exec_edges[src].setdefault(src_name, []).append((dst, dst_name))
            else:
                pulls[dst].append((dst_name, src, src_name))
                data_graph.add_edge(src, dst)
        pure = [t.spec.is_pure for t in node_types]
        self.is_pure = tuple(pure)
        self.nodes: tuple[CompiledNode, ...] = tuple(
            CompiledNode(
                index=i,
                name=node.name,
                node_type=node_types[i],
                authored=tuple((name, node_types[i].spec.attribute(f"inputs:{name}").check(value))
                               for name, value in node.inputs.items()),
                pulls=tuple(pulls[i]),
                pure_schedule=_pure_schedule(data_graph, i, pure),
                exec_targets=tuple((a.name, tuple(exec_edges[i].get(a.name, ()))) for a in node_types[i].spec.exec_outputs),
            )
            for i, node in enumerate(document.nodes)
        )
        self.event_sources = tuple(n.index for n in self.nodes if n.spec.is_event_source)
        # exec nodes each pure node depends on (through other pure nodes): their computes invalidate it
        self.pure_exec_dependencies = tuple(
            tuple(sorted(j for j in nx.ancestors(data_graph, i) if not pure[j])) if pure[i] else ()
            for i in range(len(self.nodes)))
        self.index_of = index_of
        self.variable_types = {v.name: parse_type(v.type) for v in document.variables}
        self.variable_defaults = {v.name: (parse_type(v.type).coerce(v.default) if v.default is not None
                                           else parse_type(v.type).default_value()) for v in document.variables}
        self.step_budget = int(document.settings.get("stepBudget", DEFAULT_STEP_BUDGET))

    def instantiate(self, world: World | None = None, **options) -> "GraphInstance":
        return GraphInstance(self, world, **options)


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


class _Values:
    """Attribute bag for inputs, outputs and state (plain attributes: fast to read and write)."""

    def __init__(self, values: dict):
        self.__dict__.update(values)

    def as_dict(self) -> dict:
        return dict(self.__dict__)


class NodeDatabase:
    """What a node's compute sees: its inputs, outputs, state and the world (see docs/architecture.md)."""

    __slots__ = ("inputs", "outputs", "state", "internal", "node_name", "spec", "_instance", "_index")

    def __init__(self, instance: "GraphInstance", node: CompiledNode):
        self._instance = instance
        self._index = node.index
        self.node_name = node.name
        self.spec = node.spec
        self.internal: dict = {}
        self.inputs = _Values({})
        self.outputs = _Values({})
        self.state = _Values({})

    def reset(self, node: CompiledNode) -> None:
        spec = node.spec
        self.inputs = _Values({a.name: a.initial_value() for a in spec.inputs})
        self.inputs.__dict__.update(node.authored)
        self.outputs = _Values({a.name: a.initial_value() for a in spec.outputs})
        self.state = _Values({a.name: a.initial_value() for a in spec.state})
        self.internal = {}

    @property
    def world(self) -> World:
        return self._instance.world

    @property
    def time_step(self) -> float:
        return self._instance.world.time_step

    @property
    def time(self) -> float:
        return self._instance.world.time

    @property
    def frame(self) -> int:
        return self._instance.tick_count

    @property
    def is_latent(self) -> bool:
        return self._index in self._instance._latent

    def log(self, message: str, level: str = "info") -> None:
        self._instance._log(self.node_name, level, str(message))

    def get_variable(self, name: str):
        variables = self._instance.variables
        if name not in variables:
            self.error(f"no graph variable named {name!r}")
        return variables[name]

    def set_variable(self, name: str, value) -> None:
        instance = self._instance
        if name not in instance.variables:
            self.error(f"no graph variable named {name!r}")
        instance.variables[name] = instance.compiled.variable_types[name].coerce(value)

    def error(self, message: str):
        raise GraphRuntimeError(message, self.node_name)

    def request_stop(self) -> None:
        self._instance.stop_requested = True


class GraphInstance:
    """The mutable run-time state of one compiled graph: values, state, latent set, variables."""

    def __init__(self, compiled: CompiledGraph, world: World | None = None, *,
                 on_log: Callable[[LogEvent], None] | None = None,
                 observer: Any = None):
        self.compiled = compiled
        self.world = world if world is not None else ClockWorld(compiled.document.settings.get("timeStep", 1 / 60))
        self.on_log = on_log
        self.observer = observer   # optional: .on_compute(tick, node_name, fired: list[str]) for traces
        self._databases = [NodeDatabase(self, node) for node in compiled.nodes]
        self.reset()

    # ---------------------------------------------------------------- state
    def reset(self) -> None:
        """Back to the initial state: authored inputs, default outputs and state, variables, no latent node."""
        self.tick_count = 0
        self.stop_requested = False
        self.events: deque[LogEvent] = deque(maxlen=KEPT_LOG_EVENTS)
        self.compute_counts = [0] * len(self.compiled.nodes)
        self.variables = dict(self.compiled.variable_defaults)
        self._latent: dict[int, None] = {}     # insertion-ordered set
        self._exec_epoch = 0
        self._last_exec_compute = [0] * len(self.compiled.nodes)
        self._pure_stamp = [(-1, -1)] * len(self.compiled.nodes)
        for node, database in zip(self.compiled.nodes, self._databases):
            database.reset(node)
            if node.node_type.initialize is not None:
                node.node_type.initialize(database)

    def database(self, node_name: str) -> NodeDatabase:
        return self._databases[self.compiled.index_of[node_name]]

    def output(self, node_name: str, name: str):
        return getattr(self.database(node_name).outputs, name)

    def set_input(self, node_name: str, name: str, value) -> None:
        database = self.database(node_name)
        attribute = database.spec.attribute(f"inputs:{name}")
        if attribute is None:
            raise KeyError(f"node '{node_name}' has no input '{name}'")
        setattr(database.inputs, name, attribute.attr_type.coerce(value))

    def set_state(self, node_name: str, name: str, value) -> None:
        setattr(self.database(node_name).state, name, value)

    # ---------------------------------------------------------------- ticking
    def tick(self) -> None:
        """Evaluate one tick: event sources, then latent continuations, draining the exec stack."""
        self.tick_count += 1
        self._computes_this_tick = 0
        latent_before = list(self._latent)
        for index in self.compiled.event_sources:
            self._run_from(index, None)
        for index in latent_before:
            if index in self._latent:
                self._run_from(index, None)

    def _run_from(self, index: int, pin: str | None) -> None:
        stack = [(index, pin)]
        nodes = self.compiled.nodes
        budget = self.compiled.step_budget
        while stack:
            index, pin = stack.pop()
            self._computes_this_tick += 1
            if self._computes_this_tick > budget:
                raise self._budget_error()
            self._compute(index, () if pin is _REENTRY or pin is None else (pin,))
            outputs = self._databases[index].outputs.__dict__
            reentry_pushed = False
            for name, targets in reversed(nodes[index].exec_targets):
                state = outputs[name]
                if state == _DISABLED:
                    continue
                if state == _LATENT_PUSH:
                    self._latent[index] = None
                    continue
                if state == _LATENT_FINISH:
                    self._latent.pop(index, None)
                elif state == _ENABLED_AND_PUSH and not reentry_pushed:
                    stack.append((index, _REENTRY))
                    reentry_pushed = True
                for target in reversed(targets):
                    stack.append(target)

    def compute_node(self, node_name: str, pins: tuple[str, ...] = ()) -> None:
        """Compute one node with the given exec inputs enabled, without pushing downstream (test harness)."""
        index = self.compiled.index_of[node_name]
        self._compute(index, pins)
        outputs = self._databases[index].outputs.__dict__
        for attribute in self.compiled.nodes[index].spec.exec_outputs:
            if outputs[attribute.name] == _LATENT_PUSH:
                self._latent[index] = None
            elif outputs[attribute.name] == _LATENT_FINISH:
                self._latent.pop(index, None)

    def _compute(self, index: int, pins: tuple[str, ...]) -> None:
        node = self.compiled.nodes[index]
        database = self._databases[index]
        self._pull(node, database)
        inputs, outputs = database.inputs.__dict__, database.outputs.__dict__
        for attribute in node.spec.exec_inputs:
            inputs[attribute.name] = _ENABLED if attribute.name in pins else _DISABLED
        for attribute in node.spec.exec_outputs:
            outputs[attribute.name] = _DISABLED
        self._exec_epoch += 1
        self._last_exec_compute[index] = self._exec_epoch
        self.compute_counts[index] += 1
        self._call(node, database)
        if self.observer is not None:
            fired = [a.name for a in node.spec.exec_outputs if outputs[a.name] != _DISABLED]
            self.observer.on_compute(self.tick_count, node.name, fired, database)

    def _pull(self, node: CompiledNode, database: NodeDatabase) -> None:
        databases = self._databases
        for pure_index in node.pure_schedule:
            if self._pure_is_stale(pure_index):
                pure_node = self.compiled.nodes[pure_index]
                pure_database = databases[pure_index]
                inputs = pure_database.inputs.__dict__
                for name, source, source_name in pure_node.pulls:
                    inputs[name] = databases[source].outputs.__dict__[source_name]
                self._pure_stamp[pure_index] = (self.tick_count, self._exec_epoch)
                self.compute_counts[pure_index] += 1
                self._call(pure_node, pure_database)
        inputs = database.inputs.__dict__
        for name, source, source_name in node.pulls:
            inputs[name] = databases[source].outputs.__dict__[source_name]

    def _pure_is_stale(self, index: int) -> bool:
        tick, epoch = self._pure_stamp[index]
        if tick != self.tick_count:
            return True
        last = self._last_exec_compute
        return any(last[j] > epoch for j in self.compiled.pure_exec_dependencies[index])

    def _call(self, node: CompiledNode, database: NodeDatabase) -> None:
        try:
            node.node_type.compute(database)
        except GraphRuntimeError:
            raise
        except Exception as error:
            raise GraphRuntimeError(f"{node.spec.id} failed: {type(error).__name__}: {error}", node.name) from error

    def _budget_error(self) -> StepBudgetExceeded:
        busiest = Counter({node.name: count for node, count in zip(self.compiled.nodes, self.compute_counts)})
        names = ", ".join(name for name, _ in busiest.most_common(4))
        return StepBudgetExceeded(
            f"tick {self.tick_count}: more than {self.compiled.step_budget} node computes in one tick; "
            f"runaway execution loop through {names} (raise settings.stepBudget if the loop is intended)")

    def _log(self, node_name: str, level: str, message: str) -> None:
        event = LogEvent(self.tick_count, self.world.time, node_name, level.lower(), message)
        self.events.append(event)
        log.log(getattr(logging, level.upper(), logging.INFO), "%s: %s", node_name, message)
        if self.on_log is not None:
            self.on_log(event)
