"""The seam between the engine and a physics backend.

The executor only needs a clock that advances one fixed step at a time; nodes
need a node-facing API to read and act on prims. Both are described here
without importing any physics engine: ``graphflow.physics`` implements
``World`` on PyBullet, ``ClockWorld`` below serves graphs that name no stage.

Tick order (documented in docs/architecture.md): ``world.step()`` advances
physics one step and then runs the post-step services (the surface-gripper
manager); after that every graph instance ticks once.
"""
from __future__ import annotations

from typing import Callable, Protocol, Sequence, runtime_checkable


class WorldError(RuntimeError):
    """A node asked the world for something it cannot do (unknown prim, bad attribute, ...)."""


@runtime_checkable
class World(Protocol):
    """What the executor and the nodes may use. Quaternions are (x, y, z, w)."""

    time_step: float     # seconds per physics step
    time: float          # simulated seconds since the last reset
    step_index: int      # physics steps since the last reset

    def step(self) -> None:
        """Advance physics one step, then run the post-step services."""

    def reset(self) -> None:
        """Return to the initial state, bit for bit."""

    def add_post_step_service(self, service: Callable[[float], None]) -> None:
        """Run ``service(dt)`` right after every physics step, in registration order."""

    # node-facing queries and actions (prim paths in, plain Python values out)
    def prim_pose(self, path: str) -> tuple[tuple[float, float, float], tuple[float, float, float, float]]: ...
    def prim_velocity(self, path: str) -> tuple[tuple[float, float, float], tuple[float, float, float]]: ...
    def joint_names(self, articulation_path: str) -> tuple[str, ...]: ...
    def joint_positions(self, articulation_path: str) -> tuple[float, ...]: ...
    def joint_velocities(self, articulation_path: str) -> tuple[float, ...]: ...
    def set_joint_targets(self, articulation_path: str, indices: Sequence[int], *,
                          positions: Sequence[float] | None = None,
                          velocities: Sequence[float] | None = None,
                          efforts: Sequence[float] | None = None) -> None: ...
    def get_attribute(self, prim_path: str, name: str): ...
    def set_attribute(self, prim_path: str, name: str, value) -> None: ...


class ClockWorld:
    """A world with no physics: a fixed-step clock, for graphs that name no stage."""

    def __init__(self, time_step: float = 1.0 / 60.0):
        if not time_step > 0:
            raise ValueError(f"time step must be positive, got {time_step}")
        self.time_step = time_step
        self.time = 0.0
        self.step_index = 0
        self._services: list[Callable[[float], None]] = []

    def step(self) -> None:
        self.step_index += 1
        self.time = self.step_index * self.time_step
        for service in self._services:
            service(self.time_step)

    def reset(self) -> None:
        self.time = 0.0
        self.step_index = 0

    def add_post_step_service(self, service: Callable[[float], None]) -> None:
        self._services.append(service)

    def _no_physics(self, *_args, **_kwargs):
        raise WorldError("this graph names no stage, so there are no prims to read or write")

    prim_pose = prim_velocity = joint_names = joint_positions = joint_velocities = _no_physics
    set_joint_targets = get_attribute = set_attribute = _no_physics
