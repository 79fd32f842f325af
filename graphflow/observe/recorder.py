"""Recording a run's trace (docs/trace.md): each tick is captured cheaply, then encoded as its record.

Capturing keeps what cannot wait (values a node may overwrite, the gripper's sample,
sampled body poses, this tick's pulses and log lines): one pickle of the tick's plain
values, the poses' reads and a close's rays; encoding reads them back into the records
of changes. A trace written to a stream encodes
every tick as it ends; a run report keeps its records in memory and encodes the
captured ticks only when they are read (``flush``), so the run itself pays only for
the capture. Both go through the same ``_encode``: the records are identical.
"""
from __future__ import annotations

import pickle
from operator import getitem
from typing import IO, Any, Iterator, Sequence

from graphflow.observe.trace import (
    TRACE_FORMAT,
    TRACE_VERSION,
    GripperSample,
    dumps_record,
    gripper_fields,
    loaded_versions,
    phase_outputs,
    same_path_text,
    surface_gripper_manager,
    to_json_value,
    used_grippers,
)
from graphflow.ros2.bus import published_this_tick
from graphflow.types import ExecState

_STATE_SUFFIX = {ExecState.ENABLED: "", ExecState.ENABLED_AND_PUSH: ":push",
                 ExecState.LATENT_PUSH: ":latentPush", ExecState.LATENT_FINISH: ":latentFinish"}


class TraceRecorder:
    """Writes the trace of a simulation's first graph instance to a text stream: a header, then a line per tick.

    ``TraceRecorder(simulation, stream)`` writes the header and adds itself to the simulation's
    listeners: it captures each tick after it ran (``on_tick``), with the exec pulses the instance
    logged for it (``reads_pulses``). The stream stays open: whoever opened it closes it. *records*, a list, also
    keeps every record as a dict (the run report reads them so, without encoding JSON). *deferred*
    (only without a stream): ticks are encoded into *records* only when ``flush()`` asks.
    """

    def __init__(self, simulation, stream: IO[str] | None, *, graph: str | None = None, records: list | None = None,
                 randomized: Sequence[dict] = (), deferred: bool = False):
        from graphflow.observe.trace_scene import SceneSection

        self.simulation = simulation
        self._world = simulation.world
        self.stream = stream
        self.records = records
        self.deferred = deferred and stream is None
        self.instance = simulation.instance
        self._captured: list = []                  # ticks captured but not yet encoded, flat (see on_tick)
        self._pending = 0                          # how many ticks _captured holds
        self._grippers: dict[str, Any] = {}        # each gripper's sample as last encoded
        self._manager = None                       # the world's gripper manager, once a node has made it
        self._statuses: dict[str, str] = {}        # each gripper's status token as last captured
        nodes = self.instance.compiled.nodes
        self._pulse_texts = _PulseTexts(node.name for node in nodes)   # (node index, output, state) -> text
        databases = [self.instance.database(node.name) for node in nodes]
        exec_names = [frozenset(a.name for a in node.spec.exec_outputs) for node in nodes]
        slots = [(database.outputs.__dict__, name, f"{node.name}.{name}")
                 for node, database, names in zip(nodes, databases, exec_names)
                 for name in database.outputs.__dict__ if name not in names]
        self._output_dicts = [outputs for outputs, _name, _key in slots]   # where each data output lives: its
        self._output_names = [name for _outputs, name, _key in slots]      # node's outputs, by name
        self._keys = [key for _outputs, _name, key in slots]
        self._raw: list[Any] = [_MISSING] * len(slots)   # each output as last encoded, to skip unchanged ones
        self._outputs = {key: to_json_value(outputs[name]) for outputs, name, key in slots}
        self._scene = SceneSection(simulation)
        description = getattr(simulation.world, "description", None)
        self._used_grippers = used_grippers(simulation)
        self._unused = {g.path for g in getattr(description, "surface_grippers", ())} - set(self._used_grippers)
        self._write_header(graph, list(randomized))
        simulation.add_listener(self)

    reads_pulses = True   # the instance logs each tick's exec pulses for on_tick (GraphInstance.pulse_log)

    def on_tick(self, simulation, tick: int) -> None:
        """Capture the tick that just ran (below); write its record now unless deferred.

        The capture is read now (later ticks overwrite it): per tick, one pickle of plain values (the
        time, pulses, output values, log lines, topics, gripper samples, compute counts: a deep copy in
        one compact string, so a long run keeps little and the nodes' own objects are freed as in a run
        without a report), then the scene's body poses when sampled (read now, composed when encoded) and
        the rays of a close that began, or None each. Every call here runs each tick, so there are few."""
        instance, world = self.instance, self._world
        events = instance.events
        row = [instance.tick_count, world.time, list(map(self._pulse_texts.__getitem__, instance.pulse_log or ())),
               list(map(getitem, self._output_dicts, self._output_names)),
               self._log_lines() if events and events[-1].tick == instance.tick_count else None,
               published_this_tick(world) or None]
        closing = self._sample_grippers(world, row)
        poses, rays = self._scene.capture(closing, row)
        try:
            blob = pickle.dumps(row, _PICKLE)
        except _UNPICKLABLE:   # some output value pickle cannot copy: that one as its JSON value, now
            row[_VALUES] = [_picklable(value) for value in row[_VALUES]]
            blob = pickle.dumps(row, _PICKLE)
        self._captured += (blob, poses, rays)
        self._pending += 1
        if not self.deferred:
            self.flush()

    def flush(self) -> None:
        """Encode the ticks captured since the last flush into ``records`` (and the stream)."""
        captured, self._captured = self._captured, []
        items = iter(captured)
        for _tick in range(self._pending):
            self._emit(self._encode(items))
        self._pending = 0

    def _log_lines(self) -> list:
        """The tick's log lines as (node, level, message)."""
        events, tick = self.instance.events, self.instance.tick_count
        lines = []
        for event in reversed(events):   # this tick's lines are the newest
            if event.tick != tick:
                break
            lines.append((event.node, event.level, event.message))
        return lines[::-1]

    def _sample_grippers(self, world, row: list) -> list | None:
        """Append each surface gripper's (path, sample fields) to *row*, as a list; return the grippers whose
        close began this tick (the scene records their rays), or None."""
        manager = self._manager
        if manager is None:
            manager = self._manager = surface_gripper_manager(world)
        closing, samples = None, []
        if manager is not None:
            components, statuses = manager.components, self._statuses
            for path in sorted(components):
                component = components[path]
                fields = gripper_fields(world, component)
                samples.append((path, *fields))
                if fields[0] != statuses.get(path, "Open"):
                    if statuses.get(path, "Open") == "Open":
                        closing = [*(closing or ()), component]
                    statuses[path] = fields[0]
        row.append(samples)
        return closing

    def _encode(self, items: Iterator) -> dict:
        """The next captured tick's record (*items* reads ``_captured`` in order): pulses, changed outputs,
        changed gripper fields, topics, log lines, scene fields."""
        take = items.__next__
        tick, time, pulses, values, logs, topics, samples, counts = pickle.loads(take())
        record: dict[str, Any] = {"tick": tick, "t": time}
        if pulses:
            record["pulses"] = pulses
        changed = self._changed_outputs(values)
        if changed:
            record["outputs"] = changed
        grippers = {}
        for path, *fields in samples:
            sample = GripperSample(*fields)
            if path in self._unused:
                continue    # a stage gripper the graph does not use
            previous = self._grippers.get(path)
            self._grippers[path] = sample
            if previous == sample and sample.force == sample.force and sample.held_z == sample.held_z:
                continue    # unchanged (NaN never equals itself: those go the long way)
            fields_now = sample.fields()
            old = previous.fields() if previous is not None else {}
            delta = {key: value for key, value in fields_now.items() if _changed(old.get(key, _MISSING), value)}
            if delta:
                grippers[path] = delta
        if grippers:
            record["grippers"] = grippers
        if topics:
            record["topics"] = topics
        if logs:
            record["log"] = [{"node": node, "level": level, "message": message} for node, level, message in logs]
        record.update(self._scene.encode(counts, take(), take()))
        return record

    def _emit(self, record: dict) -> None:
        if self.records is not None:
            self.records.append(record)
        if self.stream is not None:
            self.stream.write(dumps_record(record) + "\n")

    def _changed_outputs(self, values: list) -> dict[str, Any]:
        """Outputs whose value changed; a scalar, or a tuple of scalars, equal to the last one captured is skipped
        unconverted (the captures are copies, so equal means equal then and now)."""
        changed, written, last_raw, keys = {}, self._outputs, self._raw, self._keys
        for index, raw in enumerate(values):
            previous = last_raw[index]
            kind = type(raw)
            plain = kind in _SCALAR_TYPES or (kind is tuple and set(map(type, raw)) <= _SCALAR_TYPES)   # as written
            if plain and kind is type(previous) and previous == raw:
                continue
            last_raw[index] = raw
            key = keys[index]
            if kind in _SCALARS:   # the common case, compared without the general walk
                old = written.get(key, _MISSING)
                if old is _MISSING or (old != raw and not (raw != raw and old != old)):   # NaN stays NaN
                    changed[key] = written[key] = raw
                continue
            value = list(raw) if plain else to_json_value(raw)
            if _changed(written.get(key, _MISSING), value):
                changed[key] = written[key] = value
        return changed

    def _write_header(self, graph: str | None, randomized: list[dict]) -> None:
        document = self.simulation.document
        world = self.simulation.world
        compiled = self.instance.compiled
        header = {
            "format": TRACE_FORMAT,
            "version": TRACE_VERSION,
            "graph": same_path_text(graph if graph is not None else document.source),
            "description": document.description,
            "stage": document.settings.get("stage"),
            "timeStep": world.time_step,
            "nodes": {node.name: node.spec.id for node in compiled.nodes},
            "outputs": dict(self._outputs),   # a copy: the recorder updates its own as outputs change
            "phases": phase_outputs(compiled),
            "grippers": self._used_grippers,
            "versions": loaded_versions(),
            **self._scene.header(),
        }
        if randomized:   # only a randomized run has it, so other traces stay as they were
            header["randomized"] = randomized
        self._emit(header)


class _PulseTexts(dict):
    """(node index, exec output, state) -> ``node.output`` with the state's suffix (``:push``, ...), each made once."""

    def __init__(self, node_names):
        super().__init__()
        self.node_names = list(node_names)

    def __missing__(self, pulse: tuple) -> str:
        index, name, state = pulse
        text = self[pulse] = f"{self.node_names[index]}.{name}{_STATE_SUFFIX[ExecState(state)]}"
        return text


def _picklable(value: Any) -> Any:
    """*value* when pickle can copy it, else its JSON value as the trace would write it."""
    try:
        pickle.dumps(value, _PICKLE)
        return value
    except _UNPICKLABLE:
        return to_json_value(value)


_PICKLE = pickle.HIGHEST_PROTOCOL
_VALUES = 3   # where a captured row holds the output values
# pickle runs each object's own reduce code, so what it raises for a value it cannot copy varies: PicklingError,
# TypeError, AttributeError, and RuntimeError from USD's (Boost.Python) types such as Usd.Prim and Sdf.Path
_UNPICKLABLE = Exception
_MISSING = object()
_SCALARS = (float, int, str, bool, type(None))
_SCALAR_TYPES = frozenset(_SCALARS)


def _changed(previous: Any, value: Any) -> bool:
    """Different as written to the trace (so a NaN that stays NaN is no change)."""
    if previous is _MISSING:
        return True
    return previous != value and not _same_but_nan(previous, value)


def _same_but_nan(previous: Any, value: Any) -> bool:
    """Unequal values that are written alike: NaN where the other has NaN (plain JSON values only)."""
    if isinstance(previous, float) and isinstance(value, float):
        return previous != previous and value != value
    if isinstance(previous, list) and isinstance(value, list):
        return len(previous) == len(value) and all(a == b or _same_but_nan(a, b) for a, b in zip(previous, value))
    if isinstance(previous, dict) and isinstance(value, dict):
        return list(previous) == list(value) and all(
            previous[key] == value[key] or _same_but_nan(previous[key], value[key]) for key in previous)
    return False
