"""Running graphs against a world: one physics step, then one tick of every graph instance.

The world is built from the document's stage (through ``graphflow.physics``,
imported only when a stage is named) or is a plain ``ClockWorld``.
"""
from __future__ import annotations

import math
import os
from dataclasses import dataclass
from typing import Any, Callable, Iterable, Protocol

from graphflow.compiler import (
    compile as compile_graph,  # one compiled graph per document and registry, shared
)
from graphflow.document import GraphDocument, load_document
from graphflow.executor import GraphInstance
from graphflow.registry import Registry
from graphflow.world import DEFAULT_TIME_STEP, ClockWorld, World


@dataclass(frozen=True)
class RunResult:
    ticks: int
    time: float
    stopped_by_graph: bool


def create_world(stage=None, *, time_step: float | None = None, substeps: int | None = None, gui: bool = False,
                 base_dir=None, description=None) -> World:
    """The one world factory: a ``ClockWorld`` without a stage, else the stage on PyBullet.

    *stage*: a path (relative to *base_dir*), ``asset:NAME`` or an open ``Usd.Stage``; *description*: that
    open stage already parsed (the preflight's), so it is not parsed again;
    *time_step* None = the stage's own rate, or ``DEFAULT_TIME_STEP`` without a stage.
    """
    if stage is None:
        return ClockWorld(DEFAULT_TIME_STEP if time_step is None else time_step)
    from graphflow import physics  # only here: core-only graphs never import pybullet or pxr
    from graphflow.usd.resolver import resolve_stage

    if isinstance(stage, (str, os.PathLike)):
        stage = resolve_stage(os.fspath(stage), base_dir)
    return physics.create_world(stage, time_step=time_step, substeps=substeps, gui=gui, description=description)


def create_world_for(document: GraphDocument, *, gui: bool = False, parsed=None) -> World:
    """The world a document asks for (its settings' stage, time step and substeps).

    *parsed*: the document's stage as the preflight opened and parsed it (``validate.preflight.ParsedStage``).
    """
    settings = document.settings
    stage = settings.get("stage") if parsed is None else parsed.usd_stage
    return create_world(stage, time_step=settings.get("timeStep"), substeps=settings.get("substeps"), gui=gui,
                        base_dir=document.base_dir, description=None if parsed is None else parsed.description)


class Listener(Protocol):
    """Follows a simulation tick by tick: traces, progress lines, real-time pacing, video, log printing.

    Every method is optional; the simulation calls those a listener has, in the order listeners
    were added:

    * ``on_tick(simulation, tick)``: after every ``step()``, once the world and every instance ticked
      (*tick* counts the steps since the simulation was made or reset);
    * ``on_compute(instance, node_name, fired, db)``: after every node compute of every instance
      (*fired*: the exec outputs it left enabled). It is on the executor's hot path: only per-node
      timing uses it (a trace reads the instance's ``pulse_log``, which ``reads_pulses = True`` turns on);
    * ``on_log(event)``: every ``db.log`` line of every instance, as it is logged;
    * ``on_end(simulation, result)``: once when ``run()`` ends; *result* is the ``RunResult``, or None
      when the run ended by an exception (a failing node, an interrupt), which then propagates.
    """

    def on_tick(self, simulation: "Simulation", tick: int) -> None: ...


class Simulation:
    """A world plus one or more instances of one compiled graph, ticked in lockstep, and its listeners."""

    def __init__(self, document: GraphDocument, *, world: World | None = None, gui: bool = False,
                 instances: int = 1, registry: Registry | None = None, listeners: Iterable[Any] = ()):
        self.document = document
        self.compiled = compile_graph(document, registry)   # a bad document fails before a world is built
        self.world = world if world is not None else create_world_for(document, gui=gui)
        self.tick_count = 0
        self.listeners: list[Any] = list(listeners)
        self._tick_listeners: tuple[Callable[[Simulation, int], None], ...] = tuple(
            listener.on_tick for listener in self.listeners if getattr(listener, "on_tick", None) is not None)
        self.instances: list[GraphInstance] = [
            GraphInstance(self.compiled, self.world, listeners=self.listeners) for _ in range(instances)]

    @classmethod
    def load(cls, path, **options) -> "Simulation":
        return cls(load_document(path), **options)

    @property
    def instance(self) -> GraphInstance:
        return self.instances[0]

    def add_listener(self, listener: Any) -> None:
        """Attach a ``Listener``: it hears every tick, compute, log line and run end from now on."""
        self.listeners.append(listener)
        on_tick = getattr(listener, "on_tick", None)
        if on_tick is not None:
            self._tick_listeners += (on_tick,)
        for instance in self.instances:
            instance.add_listener(listener)

    def step(self) -> None:
        """Physics step (with post-step services), then every graph instance ticks once, then ``on_tick``."""
        self.world.step()
        for instance in self.instances:
            instance.tick()
        self.tick_count = tick = self.tick_count + 1
        for on_tick in self._tick_listeners:
            on_tick(self, tick)

    def tick_limit(self, *, ticks: int | None = None, seconds: float | None = None) -> int | None:
        """How many steps ``run(ticks=, seconds=)`` takes at most (None: until the graph stops)."""
        limit = ticks
        if seconds is not None:
            by_time = math.ceil(seconds / self.world.time_step - 1e-9)
            limit = by_time if limit is None else min(limit, by_time)
        return limit

    def run(self, *, ticks: int | None = None, seconds: float | None = None) -> RunResult:
        """Step until the tick limit, the time limit, or a graph asks to stop; then the run-end event
        sources (OnClosing) of each instance compute once, and ``on_end``."""
        limit = self.tick_limit(ticks=ticks, seconds=seconds)
        result = None
        try:
            outcome = self._run(limit)
            for instance in self.instances:
                instance.end_run()
            result = outcome
        finally:
            for listener in list(self.listeners):
                on_end = getattr(listener, "on_end", None)
                if on_end is not None:
                    on_end(self, result)
        return result

    def _run(self, limit: int | None) -> RunResult:
        step, instances = self.step, self.instances
        count = 0
        while limit is None or count < limit:
            step()
            count += 1
            for instance in instances:
                if instance.stop_requested:
                    return RunResult(count, self.world.time, True)
        return RunResult(count, self.world.time, False)

    def reset(self) -> None:
        self.world.reset()
        for instance in self.instances:
            instance.reset()
        self.tick_count = 0

    def close(self) -> None:
        close = getattr(self.world, "close", None)
        if close is not None:
            close()

    def __enter__(self):
        return self

    def __exit__(self, *_exc):
        self.close()
