"""Running graphs against a world: one physics step, then one tick of every graph instance.

The world is built from the document's stage (through ``graphflow.physics``,
imported only when a stage is named) or is a plain ``ClockWorld``.
"""
from __future__ import annotations

import math
import weakref
from dataclasses import dataclass
from typing import Callable

from .document import GraphDocument, load_document
from .executor import CompiledGraph, GraphInstance, LogEvent
from .registry import Registry, default_registry
from .world import ClockWorld, World

DEFAULT_TIME_STEP = 1.0 / 60.0
_compiled_graphs: "weakref.WeakValueDictionary[tuple[int, int], CompiledGraph]" = weakref.WeakValueDictionary()


def compile_graph(document: GraphDocument, registry: Registry | None = None) -> CompiledGraph:
    """The compiled graph of *document*, shared by every Simulation of that document (and registry).

    A compiled graph is immutable, so N worlds running one graph share its tables
    and generated code instead of holding N copies (see benchmarks/instances.py).
    Kept while some simulation uses it; it keeps its document alive, so the id key
    cannot be reused meanwhile.
    """
    registry = registry or default_registry()
    key = (id(document), id(registry))
    compiled = _compiled_graphs.get(key)
    if compiled is None or compiled.document is not document or compiled.registry is not registry:
        compiled = _compiled_graphs[key] = CompiledGraph(document, registry)
    return compiled


@dataclass(frozen=True)
class RunResult:
    ticks: int
    time: float
    stopped_by_graph: bool


def create_world_for(document: GraphDocument, *, gui: bool = False) -> World:
    """The world a document asks for: its stage on PyBullet, or a clock when it names none."""
    settings = document.settings
    stage = settings.get("stage")
    if stage is None:
        return ClockWorld(settings.get("timeStep", DEFAULT_TIME_STEP))
    from . import physics  # only here: core-only graphs never import pybullet or pxr

    return physics.create_world(physics.resolve_stage(stage, document.base_dir),
                                time_step=settings.get("timeStep"), substeps=settings.get("substeps"), gui=gui)


class Simulation:
    """A world plus one or more instances of one compiled graph, ticked in lockstep."""

    def __init__(self, document: GraphDocument, *, world: World | None = None, gui: bool = False,
                 instances: int = 1, registry: Registry | None = None,
                 on_log: Callable[[LogEvent], None] | None = None, observer=None):
        self.document = document
        self.world = world if world is not None else create_world_for(document, gui=gui)
        self.compiled = compile_graph(document, registry)
        self.instances: list[GraphInstance] = [
            self.compiled.instantiate(self.world, on_log=on_log, observer=observer) for _ in range(instances)]

    @classmethod
    def load(cls, path, **options) -> "Simulation":
        return cls(load_document(path), **options)

    @property
    def instance(self) -> GraphInstance:
        return self.instances[0]

    def step(self) -> None:
        """Physics step (with post-step services), then every graph instance ticks once."""
        self.world.step()
        for instance in self.instances:
            instance.tick()

    def run(self, *, ticks: int | None = None, seconds: float | None = None,
            progress: Callable[[int, int | None], None] | None = None) -> RunResult:
        """Step until the tick limit, the time limit, or a graph asks to stop."""
        limit = ticks
        if seconds is not None:
            by_time = math.ceil(seconds / self.world.time_step - 1e-9)
            limit = by_time if limit is None else min(limit, by_time)
        step, instances = self.step, self.instances
        count = 0
        while limit is None or count < limit:
            step()
            count += 1
            if progress is not None:
                progress(count, limit)
            for instance in instances:
                if instance.stop_requested:
                    return RunResult(count, self.world.time, True)
        return RunResult(count, self.world.time, False)

    def reset(self) -> None:
        self.world.reset()
        for instance in self.instances:
            instance.reset()

    def close(self) -> None:
        close = getattr(self.world, "close", None)
        if close is not None:
            close()

    def __enter__(self):
        return self

    def __exit__(self, *_exc):
        self.close()
