"""The action-graph executor: exec push along an explicit stack, data pull with per-tick memoisation.

``CompiledGraph`` is built once from a validated document (immutable: ids,
connection tables, pull schedules). ``GraphInstance`` holds everything that
changes at run time, so ``reset()`` restores the initial state and one compiled
graph can be instanced many times side by side.

Speed (see benchmarks/dispatch.py): everything a tick needs is resolved once.
The compiled graph keeps, per node, its exec pin names, its exec fan-out as
ready-made stack entries, and a *pull program*: the pure nodes its data pulls
depend on, in order, as one generated Python function of straight-line code
(stale check, copy each input, compute; ``CompiledGraph.pull_source`` shows
it). Each instance binds those to its own value dicts (the ``__dict__`` of
every node's inputs / outputs bags, which live as long as the instance), so a
tick is list indexing, dict stores of pulled values and compute calls: no name
resolution, no spec walks, no tuples or lists built per node.
"""
from __future__ import annotations

import logging
from collections import Counter, deque
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Callable, Iterable, NoReturn

from graphflow.compiled import CompiledGraph, CompiledNode
from graphflow.errors import RunFailure
from graphflow.files import one_line
from graphflow.messages import usd_message
from graphflow.types import MAX_VALUE_DEPTH, ExecState, nesting_exceeds
from graphflow.world import DEFAULT_TIME_STEP, ClockWorld, World

KEPT_LOG_EVENTS = 10_000   # the event log keeps the newest lines so long runs stay flat in memory
log = logging.getLogger("graphflow.graph")

_DISABLED = ExecState.DISABLED
_ENABLED = ExecState.ENABLED
_ENABLED_AND_PUSH = ExecState.ENABLED_AND_PUSH
_LATENT_PUSH = ExecState.LATENT_PUSH
_LATENT_FINISH = ExecState.LATENT_FINISH


def _discard(_entry) -> None:
    """Where ``compute_node`` sends the entries a compute enables: nowhere."""


def _refusal(line: str):
    """The compute of a node whose prim is missing: it fails with the importer's line the first time it runs."""
    def compute(db):
        error = GraphRuntimeError(f"node '{db.node_name}' {line}")
        error.node = db.node_name
        raise error
    return compute


class GraphRuntimeError(RunFailure):
    """A run-time failure naming the node (exit code 1 from the CLI)."""

    def __init__(self, message: str, node: str | None = None):
        self.node = node
        super().__init__(one_line(f"node '{node}': {message}" if node else message))


class StepBudgetExceeded(GraphRuntimeError):
    """More node computes in one tick than the budget allows: an exec loop that never ends."""


@dataclass(frozen=True)
class LogEvent:
    tick: int
    time: float
    node: str
    level: str
    message: str


class _Values:
    """Attribute bag for inputs, outputs and state (plain attributes: fast to read and write)."""

    def __init__(self, values: dict):
        self.__dict__.update(values)

    def as_dict(self) -> dict:
        return dict(self.__dict__)


def _refill(values: _Values, initial: dict) -> None:
    values.__dict__.clear()
    values.__dict__.update(initial)


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
        """Initial values, refilled in place: the instance's pull tables hold these very dicts."""
        spec = node.spec
        _refill(self.inputs, {a.name: a.initial_value() for a in spec.inputs})
        self.inputs.__dict__.update(node.authored)
        _refill(self.outputs, {a.name: a.initial_value() for a in spec.outputs})
        _refill(self.state, {a.name: a.initial_value() for a in spec.state})
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

    @property
    def base_dir(self) -> Path:
        """The graph file's folder: files a node names relative to the graph are found from here."""
        return self._instance.compiled.document.base_dir

    @property
    def connected_exec_outputs(self) -> frozenset[str]:
        """Exec outputs wired to something: Kit nodes whose output count is dynamic (Multigate) count these."""
        node = self._instance.compiled.nodes[self._index]
        return frozenset(name for name, targets in node.exec_targets if targets)

    def exec_input_sources(self, name: str) -> int:
        """How many exec outputs are wired into the exec input *name* (SyncGate waits for each of them)."""
        wanted = (self._index, name)
        return sum(targets.count(wanted) for node in self._instance.compiled.nodes
                   for _output, targets in node.exec_targets)

    def log(self, message: str, level: str = "info") -> None:
        self._instance._log(self.node_name, level, str(message))

    # ReadOmniGraphValue: another node's attribute by name, without a connection
    def node_value(self, node_name: str, attribute: str):
        """The value *node_name*'s ``inputs:``/``outputs:``/``state:`` *attribute* holds now (as it last computed).

        Raises KeyError with a one-line reason when the graph has no such node or the node no such attribute.
        """
        instance = self._instance
        if node_name not in instance.compiled.index_of:
            raise KeyError(f"this graph has no node named {node_name!r}")
        other = instance.database(node_name)
        group, _, name = attribute.partition(":")
        bag = {"inputs": other.inputs, "outputs": other.outputs, "state": other.state}.get(group)
        if bag is None or other.spec.attribute(attribute) is None:
            raise KeyError(f"node {node_name!r} ({other.spec.id}) has no attribute {attribute!r}")
        return getattr(bag, name)

    def get_variable(self, name: str):
        variables = self._instance.variables
        if name not in variables:
            self.error(f"no graph variable named {name!r}")
        return variables[name]

    def set_variable(self, name: str, value) -> None:
        instance = self._instance
        if name not in instance.variables:
            self.error(f"no graph variable named {name!r}")
        variable_type = instance.compiled.variable_types[name]
        value = variable_type.coerce(value)
        # an `any` variable fed (x, x) every tick nests one level deeper a tick; printing or tracing it doubles
        if variable_type.is_any and isinstance(value, tuple) and nesting_exceeds(value):
            self.error(f"variable {name!r}: value nests more than {MAX_VALUE_DEPTH} levels deep")
        instance.variables[name] = value

    def error(self, message: str) -> NoReturn:
        raise GraphRuntimeError(message, self.node_name)

    def request_stop(self) -> None:
        self._instance.stop_requested = True


class GraphInstance:
    """The mutable run-time state of one compiled graph: values, state, latent set, variables."""

    def __init__(self, compiled: CompiledGraph, world: World | None = None, *, listeners: Iterable[Any] = ()):
        self.compiled = compiled
        self.world = world if world is not None else ClockWorld(compiled.document.settings.get("timeStep", DEFAULT_TIME_STEP))
        self._compute_listeners: tuple[Callable, ...] = ()
        self.pulse_log: list[tuple[int, str, Any]] | None = None
        self._log_listeners: tuple[Callable[[LogEvent], None], ...] = ()
        for listener in listeners:   # before reset(): a node's initialize() may log
            self.add_listener(listener)
        self._databases = [NodeDatabase(self, node) for node in compiled.nodes]
        self._bind()
        self.reset()

    def add_listener(self, listener: Any) -> None:
        """Call the listener's ``on_compute`` and ``on_log``, if it has them (see ``graphflow.runtime.Listener``).

        ``on_compute(instance, node_name, fired, db)`` after every compute of this instance (*fired*: the
        exec outputs it left enabled); ``on_log(event)`` for every ``db.log`` line. A tick only pays for
        ``on_compute`` while some listener has one. A listener with ``reads_pulses`` true turns on
        ``pulse_log``: the exec outputs each compute of the tick fired, as (node index, output name, state)
        in declared order, emptied as the next tick starts (read it in ``on_tick``); a trace needs no more
        of a compute than that, and a list append costs less than a call.
        """
        on_compute, on_log = getattr(listener, "on_compute", None), getattr(listener, "on_log", None)
        if getattr(listener, "reads_pulses", False) and self.pulse_log is None:
            self.pulse_log = []
        if on_compute is not None:
            self._compute_listeners += (on_compute,)
        if on_log is not None:
            self._log_listeners += (on_log,)

    def _bind(self) -> None:
        """Bind the compiled tables to this instance's value dicts (which reset() refills in place)."""
        compiled, databases = self.compiled, self._databases
        missing = compiled.document.missing_assets()
        self._computes = tuple(_refusal(missing[node.name]) if node.name in missing else node.node_type.compute
                               for node in compiled.nodes)
        self._idles = tuple(None if node.name in missing else node.node_type.idle for node in compiled.nodes)
        self._input_dicts = tuple(database.inputs.__dict__ for database in databases)
        self._output_dicts = tuple(database.outputs.__dict__ for database in databases)
        # pulls[i]: (inputs dict of i, input name, outputs dict of the source, source output name)
        self._pulls = tuple(
            tuple((self._input_dicts[node.index], name, self._output_dicts[source], source_name)
                  for name, source, source_name in node.pulls)
            for node in compiled.nodes)
        count = len(compiled.nodes)
        self.compute_counts = [0] * count
        self._last_exec_compute = [0] * count
        self._pure_stamp = [-1] * count
        namespace = {"stamps": self._pure_stamp, "last": self._last_exec_compute, "counts": self.compute_counts,
                     "failure": self._failure, "GraphRuntimeError": GraphRuntimeError}
        for i, (in_name, out_name, compute_name, db_name) in enumerate(compiled.program_names):
            namespace[in_name], namespace[out_name] = self._input_dicts[i], self._output_dicts[i]
            namespace[compute_name], namespace[db_name] = self._computes[i], databases[i]
        self._namespace = namespace
        self._pull_programs = [None if compiled.is_pure[i] else self._bind_pull(i) for i in range(count)]

    def _bind_pull(self, index: int):
        """Node *index*'s pull program as a function of this instance (None when it pulls no pure node)."""
        code = self.compiled.pull_program(index)
        if code is None:
            return None
        exec(code, self._namespace)   # compiled once per graph: this only makes a function bound to this instance
        return self._namespace.pop("pull")

    # ---------------------------------------------------------------- state
    def reset(self) -> None:
        """Back to the initial state: authored inputs, default outputs and state, variables, no latent node."""
        count = len(self.compiled.nodes)
        self.tick_count = 0
        self.stop_requested = False
        self.events: deque[LogEvent] = deque(maxlen=KEPT_LOG_EVENTS)
        self.compute_counts[:] = [0] * count          # in place: the pull programs hold these lists
        self.variables = dict(self.compiled.variable_defaults)
        self._latent: dict[int, None] = {}     # insertion-ordered set
        self._computes_this_tick = 0
        # Memoisation clock: the epoch advances at every exec compute and at the start of every tick.
        # A pure node is fresh while its stamp (the epoch it computed at) is not older than this tick's
        # first epoch and no exec node it depends on computed after it.
        self._exec_epoch = 0
        self._tick_epoch = 0
        self._epoch_tick = 0                   # the tick_count _tick_epoch belongs to
        self._last_exec_compute[:] = [0] * count
        self._pure_stamp[:] = [-1] * count
        for node, database in zip(self.compiled.nodes, self._databases):
            database.reset(node)
            if node.node_type.initialize is not None and self._computes[node.index] is node.node_type.compute:
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
        self._exec_epoch += 1                  # _start_tick_epoch(), written out
        self._tick_epoch = self._exec_epoch
        self._epoch_tick = self.tick_count
        self._computes_this_tick = 0
        if self.pulse_log:
            self.pulse_log.clear()
        entries, run_from, latent = self.compiled.plain_entries, self._run_from, self._latent
        latent_before = list(latent) if latent else ()
        for index in self.compiled.event_sources:
            run_from(entries[index])
        for index in latent_before:
            if index in latent:
                run_from(entries[index])

    def end_run(self) -> None:
        """The run is over (after its last tick): the run-end event sources (OnClosing) compute, once."""
        if not self.compiled.run_end_sources:
            return
        self._start_tick_epoch()
        self._computes_this_tick = 0
        for index in self.compiled.run_end_sources:
            self._run_from(self.compiled.plain_entries[index])

    def _start_tick_epoch(self) -> None:
        self._exec_epoch += 1
        self._tick_epoch = self._exec_epoch
        self._epoch_tick = self.tick_count

    def _run_from(self, entry: tuple[int, tuple[str, ...]], push=None) -> None:
        """Drain the exec stack from one entry: compute a node, then push what its exec outputs enabled.

        The one compute path (this is the hot path: locals only). *push*, when given, receives the
        entries the node's exec outputs enable instead of the stack: ``compute_node`` discards them,
        so exactly one node computes, with the same pulls, pins, latent bookkeeping and counts as a tick.
        """
        compiled = self.compiled
        stack = [entry]
        pop = stack.pop
        if push is None:
            push = stack.append
        computes, idles, databases = self._computes, self._idles, self._databases
        input_dicts, output_dicts, pulls = self._input_dicts, self._output_dicts, self._pulls
        pull_programs = self._pull_programs
        exec_input_names, exec_output_names = compiled.exec_input_names, compiled.exec_output_names
        push_plans, self_entries = compiled.push_plans, compiled.plain_entries
        last_exec_compute, compute_counts, latent = self._last_exec_compute, self.compute_counts, self._latent
        compute_listeners, pulse_log = self._compute_listeners, self.pulse_log
        budget = compiled.step_budget
        count = self._computes_this_tick
        try:
            while stack:
                index, pins = pop()
                count += 1
                if count > budget:
                    raise self._budget_error()
                inputs, outputs = input_dicts[index], output_dicts[index]
                for name in exec_input_names[index]:
                    inputs[name] = _ENABLED if name in pins else _DISABLED
                for name in exec_output_names[index]:
                    outputs[name] = _DISABLED
                idle = idles[index]
                if idle is not None and idle(databases[index]):
                    continue                    # the pulse would change nothing: no pulls, no compute
                # pull: stale pure upstream nodes compute, then this node's data inputs are copied in
                pull = pull_programs[index]
                if pull is not None:
                    pull(self._tick_epoch, self._exec_epoch)
                for data_inputs, name, source, source_name in pulls[index]:
                    data_inputs[name] = source[source_name]
                self._exec_epoch = epoch = self._exec_epoch + 1
                last_exec_compute[index] = epoch
                compute_counts[index] += 1
                try:
                    computes[index](databases[index])
                except GraphRuntimeError:
                    raise
                except Exception as error:
                    raise self._failure(index, error) from error
                if compute_listeners:
                    self._tell_compute(index)
                # push: exec outputs last to first, so the first output's first target pops first
                reentry_pushed = False
                logged = len(pulse_log) if pulse_log is not None else 0
                for name, targets in push_plans[index]:
                    state = outputs[name]
                    if state == _DISABLED:
                        continue
                    if pulse_log is not None:
                        pulse_log.append((index, name, state))
                    if state == _LATENT_PUSH:
                        latent[index] = None
                        continue
                    if state == _LATENT_FINISH:
                        latent.pop(index, None)
                    elif state == _ENABLED_AND_PUSH and not reentry_pushed:
                        push(self_entries[index])   # re-enter after the downstream pushed below completes
                        reentry_pushed = True
                    for target in targets:
                        push(target)
                if pulse_log is not None and len(pulse_log) - logged > 1:
                    pulse_log[logged:] = reversed(pulse_log[logged:])   # in declared order
        finally:
            self._computes_this_tick = count

    def compute_node(self, node_name: str, pins: tuple[str, ...] = ()) -> None:
        """Compute one node with the given exec inputs enabled, without pushing downstream (test harness)."""
        index = self.compiled.index_of[node_name]
        if self._epoch_tick != self.tick_count:   # the harness advanced tick_count itself
            self._start_tick_epoch()
            self._computes_this_tick = 0
        if self._pull_programs[index] is None and self.compiled.is_pure[index]:
            self._pull_programs[index] = self._bind_pull(index)   # a pure node computed on its own
        self._run_from((index, tuple(pins)), push=_discard)

    def _tell_compute(self, index: int) -> None:
        outputs = self._output_dicts[index]
        fired = [name for name in self.compiled.exec_output_names[index] if outputs[name] != _DISABLED]
        name, database = self.compiled.nodes[index].name, self._databases[index]
        for on_compute in self._compute_listeners:
            on_compute(self, name, fired, database)

    def _failure(self, index: int, error: Exception) -> GraphRuntimeError:
        node = self.compiled.nodes[index]
        return GraphRuntimeError(f"{node.spec.id} failed: {type(error).__name__}: {usd_message(error)}", node.name)

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
        for on_log in self._log_listeners:
            on_log(event)
