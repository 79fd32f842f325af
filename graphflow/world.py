"""The seam between the engine and a physics backend.

The executor only needs a clock that advances one fixed step at a time; nodes
need a node-facing API to read and act on prims. Both are described here
without importing any physics engine: ``graphflow.physics`` implements
``World`` on PyBullet, ``ClockWorld`` below serves graphs that name no stage.

Tick order (documented in docs/architecture.md): ``world.step()`` advances
physics one step and then steps the world's services (surface-gripper manager,
keyboard, gamepad, recorder, ...) in the order they were added; after that
every graph instance ticks once.
"""
from __future__ import annotations

from typing import Callable, Protocol, Sequence, TypeVar, runtime_checkable

ServiceT = TypeVar("ServiceT")

DEFAULT_TIME_STEP = 1.0 / 60.0   # seconds; Isaac Sim's default physics rate, used when neither graph nor stage sets one


@runtime_checkable
class WorldService(Protocol):
    """Something a world owns: stepped right after every physics step, reset with the world."""

    def after_step(self, dt: float) -> None: ...

    def reset(self) -> None: ...


class Services:
    """The services of one world, one per kind (their class), stepped and reset in the order they were added.

    A world owns exactly one ``Services``; a service is found by its kind
    (``world.services.get(Keyboard)``) or created on first use
    (``world.services.require(Keyboard, make)``), never by attributes set on the
    world from outside or by module-level tables.
    """

    def __init__(self):
        self._by_kind: dict[type, WorldService] = {}

    def add(self, service: ServiceT, kind: type | None = None) -> ServiceT:
        """Add *service* as the world's one service of *kind* (default: its class), replacing any earlier one."""
        kind = kind or type(service)
        self._by_kind.pop(kind, None)
        self._by_kind[kind] = service
        return service

    def get(self, kind: type[ServiceT]) -> ServiceT | None:
        return self._by_kind.get(kind)

    def require(self, kind: type[ServiceT], make: Callable[[], ServiceT]) -> ServiceT:
        """The service of *kind*, made by ``make()`` and added on first use."""
        service = self._by_kind.get(kind)
        if service is None:
            service = self.add(make(), kind)
        return service

    def __iter__(self):
        return iter(list(self._by_kind.values()))

    def after_step(self, dt: float) -> None:
        for service in list(self._by_kind.values()):
            service.after_step(dt)

    def reset(self) -> None:
        for service in list(self._by_kind.values()):
            service.reset()


class WorldError(RuntimeError):
    """A node asked the world for something it cannot do (unknown prim, bad attribute, ...)."""


@runtime_checkable
class World(Protocol):
    """What the executor and the nodes may use. Quaternions are (x, y, z, w)."""

    time_step: float     # seconds per physics step
    time: float          # simulated seconds since the last reset
    step_index: int      # physics steps since the last reset

    services: Services   # owned by the world: stepped after each physics step, reset with it

    def step(self) -> None:
        """Advance physics one step, then step the services."""

    def reset(self) -> None:
        """Return to the initial state, bit for bit, and reset the services."""

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
    def contacts(self, path: str) -> list:
        """Contacts of the body at *path*: ``(other_prim, position, normal, distance, normal_force)`` each."""
    def gravity(self) -> tuple[float, float, float]:
        """The stage's gravity vector, m/s^2."""
    def window_keys(self):
        """The key source of the world's window (``poll(time) -> [(key, is_down)]``), or None without one."""


def on_nearest_ancestor(path: str, query: Callable[[str], ServiceT]) -> tuple[str, ServiceT]:
    """``(prim, query(prim))`` for *path* or, where the world refuses it, its nearest ancestor that it accepts.

    Sensors and publishers name a prim under the body or articulation they read.
    A relative path is refused at once (walking up it would never end); when no
    ancestor is accepted, the world's refusal of *path* itself is raised.
    """
    if not path.startswith("/"):
        raise WorldError(f"{path!r} is not an absolute prim path")
    refusal = None
    candidate = path
    while candidate:
        try:
            return candidate, query(candidate)
        except WorldError as error:
            refusal = refusal or error
        candidate = candidate.rsplit("/", 1)[0]
    raise refusal


class ClockWorld:
    """A world with no physics: a fixed-step clock, for graphs that name no stage."""

    def __init__(self, time_step: float = DEFAULT_TIME_STEP):
        if not time_step > 0:
            raise ValueError(f"time step must be positive, got {time_step}")
        self.time_step = time_step
        self.time = 0.0
        self.step_index = 0
        self.services = Services()

    def step(self) -> None:
        self.step_index += 1
        self.time = self.step_index * self.time_step
        self.services.after_step(self.time_step)

    def reset(self) -> None:
        self.time = 0.0
        self.step_index = 0
        self.services.reset()

    def window_keys(self):
        return None

    def _no_physics(self, *_args, **_kwargs):
        raise WorldError("this graph names no stage, so there are no prims to read or write")

    prim_pose = prim_velocity = joint_names = joint_positions = joint_velocities = _no_physics
    set_joint_targets = get_attribute = set_attribute = contacts = gravity = _no_physics
