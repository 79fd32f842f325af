"""Node type declarations: what a node type is, in one immutable place.

A node module (one per node type, in ``nodes/``) declares ``SPEC = NodeSpec(...)``
at the top and defines ``compute(db)`` below it, like an OmniGraph ``.ogn`` next
to its implementation. Optional module functions:

* ``initialize(db)``: runs once when an instance is created or reset, after the
  declared state has its defaults (set up Python-side caches there);
* ``validate(node_name, values) -> list[str]``: extra load-time checks of
  authored input values (each message names the attribute).

The spec holds no runtime state; per-instance values live in the executor's
instance state, so one graph document can run many times side by side.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any, Callable

from graphflow.types import AttrType, TypeMismatch, parse_type


@dataclass(frozen=True)
class Attribute:
    """One input, output or state attribute of a node type.

    ``name`` is the bare name (``execIn``); files use ``inputs:execIn``.
    ``minimum``/``maximum`` bound numeric values (each element of a tuple or
    array); ``allowed_tokens`` restricts token values.
    """

    name: str
    type: str
    default: Any = None
    description: str = ""
    optional: bool = False
    allowed_tokens: tuple[str, ...] = ()
    minimum: float | None = None
    maximum: float | None = None
    length: int | None = None  # exact array length, when the node requires one

    @property
    def attr_type(self) -> AttrType:
        return parse_type(self.type)

    @property
    def is_execution(self) -> bool:
        return self.attr_type.is_execution

    def initial_value(self):
        """The value an instance starts with: the declared default, coerced, else the type's zero."""
        if self.default is None:
            return self.attr_type.default_value()
        return self.attr_type.coerce(self.default)

    def check(self, value):
        """Coerce an authored value and check its range; raise TypeMismatch with a clear reason."""
        coerced = self.attr_type.coerce(value)
        if self.allowed_tokens and coerced not in self.allowed_tokens:
            shown = ", ".join(self.allowed_tokens[:12]) + (", ..." if len(self.allowed_tokens) > 12 else "")
            raise TypeMismatch(f"expected one of {shown}; got {value!r}")
        if self.length is not None and len(coerced) != self.length:
            raise TypeMismatch(f"expected exactly {self.length} values, got {len(coerced)}")
        if self.minimum is not None or self.maximum is not None:
            for number in _numbers(coerced):
                if not math.isfinite(number):   # NaN passes every comparison; infinity is no setting either
                    raise TypeMismatch(f"value {number} is not a finite number (the range {self._range()} "
                                       "holds finite numbers only)")
                if self.minimum is not None and number < self.minimum:
                    raise TypeMismatch(f"value {number} is below the minimum {self.minimum}")
                if self.maximum is not None and number > self.maximum:
                    raise TypeMismatch(f"value {number} is above the maximum {self.maximum}")
        return coerced

    def _range(self) -> str:
        if self.minimum is not None and self.maximum is not None:
            return f"{self.minimum:g} to {self.maximum:g}"
        return f">= {self.minimum:g}" if self.minimum is not None else f"<= {self.maximum:g}"

    def to_json(self) -> dict:
        entry = {"name": self.name, "type": self.type, "default": _jsonable(self.default),
                 "description": self.description, "optional": self.optional}
        if self.allowed_tokens:
            entry["allowedTokens"] = list(self.allowed_tokens)
        if self.minimum is not None:
            entry["minimum"] = self.minimum
        if self.maximum is not None:
            entry["maximum"] = self.maximum
        if self.length is not None:
            entry["length"] = self.length
        return entry


def _numbers(value):
    if isinstance(value, tuple):
        for item in value:
            yield from _numbers(item)
    elif isinstance(value, (int, float)) and not isinstance(value, bool):
        yield value


def _jsonable(value):
    if isinstance(value, tuple):
        return [_jsonable(v) for v in value]
    return value


@dataclass(frozen=True)
class NodeSpec:
    """The declaration of a node type: identity, documentation and typed ports."""

    id: str
    version: int
    description: str
    inputs: tuple[Attribute, ...] = ()
    outputs: tuple[Attribute, ...] = ()
    state: tuple[Attribute, ...] = ()
    categories: tuple[str, ...] = ()
    aliases: tuple[str, ...] = ()       # legacy ids that load as this type
    ui_name: str = ""
    compatible_versions: tuple[int, ...] = ()  # older typeVersions files may name
    fires_at_run_end: bool = False      # an event source computed once when a run ends, not on ticks (OnClosing)
    _by_name: dict | None = field(default=None, init=False, repr=False, compare=False)

    def __post_init__(self):
        lookup = {}
        for group, attributes in (("inputs", self.inputs), ("outputs", self.outputs), ("state", self.state)):
            for attribute in attributes:
                attribute.attr_type  # fail at import time on a bad type name
                lookup[f"{group}:{attribute.name}"] = attribute
        object.__setattr__(self, "_by_name", lookup)

    def attribute(self, qualified_name: str) -> Attribute | None:
        """Look up ``inputs:x`` / ``outputs:y`` / ``state:z``."""
        return self._by_name.get(qualified_name) if self._by_name is not None else None

    @property
    def exec_inputs(self) -> tuple[Attribute, ...]:
        return tuple(a for a in self.inputs if a.is_execution)

    @property
    def exec_outputs(self) -> tuple[Attribute, ...]:
        return tuple(a for a in self.outputs if a.is_execution)

    @property
    def is_event_source(self) -> bool:
        """No exec input and at least one exec output: starts execution chains (On* nodes)."""
        return not self.exec_inputs and bool(self.exec_outputs)

    @property
    def is_pure(self) -> bool:
        """No execution attributes: computed on demand when a consumer pulls its outputs."""
        return not self.exec_inputs and not self.exec_outputs

    def accepts_version(self, version: int) -> bool:
        return version == self.version or version in self.compatible_versions

    def to_json(self) -> dict:
        return {
            "id": self.id,
            "version": self.version,
            "description": self.description,
            "uiName": self.ui_name,
            "categories": list(self.categories),
            "aliases": list(self.aliases),
            "compatibleVersions": list(self.compatible_versions),
            "inputs": [a.to_json() for a in self.inputs],
            "outputs": [a.to_json() for a in self.outputs],
            "state": [a.to_json() for a in self.state],
        }


@dataclass(frozen=True)
class NodeType:
    """A registered node type: its spec plus the module functions that implement it."""

    spec: NodeSpec
    compute: Callable[[Any], Any]
    initialize: Callable[[Any], None] | None = None
    validate: Callable[[str, dict], list] | None = None
    # idle(db): True when this pulse would change nothing (no output, no state); the executor then skips the
    # node's pulls and compute. It may read exec inputs, state and internals, never data inputs (not pulled yet).
    idle: Callable[[Any], bool] | None = None
    module: str = ""
