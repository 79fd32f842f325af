"""What a node module sees and what it declares, as typed protocols (``compute(db: NodeDb)`` completes in an editor).

``NodeDb`` is the database a node's functions are given (implemented by ``graphflow.executor.NodeDatabase``):
its inputs, outputs and state as attribute bags named as the spec declares them, the world through the
declared backend interface, the clock, variables, logging and errors. ``NodeModule`` is the shape the
registry accepts for one node type: ``SPEC`` and ``compute``, optionally ``initialize``, ``validate``, ``idle``.
"""
from __future__ import annotations

from pathlib import Path
from typing import Any, NoReturn, Protocol, runtime_checkable

from graphflow.spec import NodeSpec
from graphflow.world import World


class ValueBag(Protocol):
    """Inputs, outputs or state: one attribute per declared port (``db.inputs.execIn``, ``db.outputs.count``)."""

    def __getattr__(self, name: str) -> Any: ...

    def __setattr__(self, name: str, value: Any) -> None: ...


class NodeDb(Protocol):
    """What ``compute(db)``, ``initialize(db)`` and ``idle(db)`` are given."""

    inputs: ValueBag
    outputs: ValueBag
    state: ValueBag
    internal: dict[str, Any]   # Python-side caches of this node instance (reset with the instance)
    node_name: str
    spec: NodeSpec

    @property
    def world(self) -> World: ...

    @property
    def time_step(self) -> float: ...

    @property
    def time(self) -> float: ...

    @property
    def frame(self) -> int: ...

    @property
    def is_latent(self) -> bool: ...

    @property
    def base_dir(self) -> Path: ...

    def log(self, message: str, level: str = "info") -> None: ...

    def node_value(self, node_name: str, attribute: str) -> Any: ...

    def get_variable(self, name: str) -> Any: ...

    def set_variable(self, name: str, value: Any) -> None: ...

    def error(self, message: str) -> NoReturn: ...

    def request_stop(self) -> None: ...


@runtime_checkable
class NodeModule(Protocol):
    """One node type's module: ``SPEC`` at the top, ``compute(db)`` below it (optional functions may be absent)."""

    SPEC: NodeSpec

    def compute(self, db: NodeDb) -> Any: ...
