"""Per-node compute times, wall clock, for a report that asks for them (never in a trace: they differ every run).

A run listener and world service: the clock starts when the physics step ends
(``after_step``, the graph evaluates next) and each ``on_compute`` charges the
time since the previous one to the node that just computed, so an exec node's
time includes the pure nodes it pulled (they compute inside its turn).
"""
from __future__ import annotations

import time


class ComputeTimer:
    """Sums wall-clock seconds and computes per node of one simulation's first instance."""

    def __init__(self, simulation):
        self.instance = simulation.instance
        self.seconds: dict[str, float] = {}
        self.computes: dict[str, int] = {}
        self._last = time.perf_counter()
        simulation.world.services.add(self)
        simulation.add_listener(self)

    def after_step(self, _dt: float) -> None:
        self._last = time.perf_counter()

    def reset(self) -> None:
        self._last = time.perf_counter()

    def on_compute(self, instance, node_name: str, _fired, _db) -> None:
        if instance is not self.instance:
            return
        now = time.perf_counter()
        self.seconds[node_name] = self.seconds.get(node_name, 0.0) + (now - self._last)
        self.computes[node_name] = self.computes.get(node_name, 0) + 1
        self._last = now

    def table(self) -> dict:
        return {name: {"computes": self.computes[name], "seconds": self.seconds[name]} for name in sorted(self.seconds)}
