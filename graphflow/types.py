"""Attribute types of graphflow, named as in OmniGraph.

Each type knows how to turn a JSON value into the Python value a node sees, and
says clearly why a value does not fit. Values are immutable (tuples, not lists)
so they can flow along connections without copies.

Python representation:
    bool -> bool; int/int64/uint/uint64 -> int; float/double -> float;
    token/string -> str; double[3], quatd[4], ... -> tuple of numbers;
    T[] -> tuple of T; target -> tuple of prim path strings;
    execution -> ExecState; any -> whatever was connected or authored;
    bundle -> graphflow.bundles.Bundle (set by connections only; connects only to bundle).

Quaternions (quatd[4], quatf[4]) are stored (x, y, z, w) as in OmniGraph
attributes and PyBullet.
"""
from __future__ import annotations

import math
import re
from dataclasses import dataclass
from enum import IntEnum
from functools import lru_cache

from graphflow.bundles import Bundle


class ExecState(IntEnum):
    """State of an execution attribute, as OmniGraph's ExecutionAttributeState."""

    DISABLED = 0
    ENABLED = 1
    ENABLED_AND_PUSH = 2
    LATENT_PUSH = 3
    LATENT_FINISH = 4


class TypeMismatch(ValueError):
    """A value does not fit an attribute type; the message says what was expected and got."""


SCALAR_KINDS = {
    "bool": "bool",
    "int": "int",
    "int64": "int",
    "uint": "uint",
    "uint64": "uint",
    "uchar": "uint",
    "float": "real",
    "double": "real",
    "half": "real",
    "timecode": "real",
    "token": "str",
    "string": "str",
    "path": "str",
}

TUPLE_BASES = {"double", "float", "half", "int"}
TUPLE_ROLES = {"quatd": "double", "quatf": "float", "quath": "half",
               "vectord": "double", "vectorf": "float", "pointd": "double", "pointf": "float",
               "normald": "double", "normalf": "float", "colord": "double", "colorf": "float",
               "matrixd": "double", "colorh": "half", "normalh": "half", "pointh": "half", "vectorh": "half",
               "texcoordd": "double", "texcoordf": "float", "texcoordh": "half"}

# the values each scalar type can hold (OmniGraph's int and uint are 32-bit, float is 32-bit IEEE)
INTEGER_RANGES = {"uchar": (0, 255), "int": (-2**31, 2**31 - 1), "int64": (-2**63, 2**63 - 1), "uint": (0, 2**32 - 1),
                  "uint64": (0, 2**64 - 1)}
REAL_LIMITS = {"float": 3.4028234663852886e38, "half": 65504.0}

EMPTY_BUNDLE = Bundle()
_TYPE_PATTERN = re.compile(r"^(?P<base>[a-z0-9]+)(\[(?P<n>\d+)\])?(?P<array>\[\])?$")


@dataclass(frozen=True)
class AttrType:
    """A parsed attribute type name such as ``double``, ``double[3]``, ``token[]``, ``double[3][]``."""

    name: str
    base: str            # scalar base name ("double", "token", "execution", "target", "any")
    tuple_size: int      # 0 for a scalar
    is_array: bool

    @property
    def is_execution(self) -> bool:
        return self.base == "execution"

    @property
    def is_any(self) -> bool:
        return self.base == "any"

    @property
    def is_target(self) -> bool:
        return self.base == "target"

    @property
    def is_bundle(self) -> bool:
        return self.base == "bundle"

    def default_value(self):
        """The value an unset attribute of this type holds."""
        if self.is_execution:
            return ExecState.DISABLED
        if self.is_bundle:
            return EMPTY_BUNDLE
        if self.is_array or self.is_target:
            return ()
        if self.is_any:
            return None
        kind = SCALAR_KINDS[self.base]
        zero = {"bool": False, "int": 0, "uint": 0, "real": 0.0, "str": ""}[kind]
        if self.tuple_size:
            return tuple(zero for _ in range(self.tuple_size))
        return zero

    def coerce(self, value):
        """Turn a JSON value into this type's Python value or raise TypeMismatch."""
        if self.is_any:
            return _freeze(value)
        if self.is_execution:
            raise TypeMismatch(f"expected {self.name} (set by connections only), got {_show(value)}")
        if self.is_bundle:
            if isinstance(value, Bundle):
                return value
            raise TypeMismatch(f"expected a bundle (set by connections only), got {_show(value)}")
        if self.is_target:
            return _coerce_target(value, self.name)
        if self.is_array:
            if not isinstance(value, (list, tuple)):
                raise TypeMismatch(f"expected {self.name}, got {_show(value)}")
            element = element_type(self)
            try:
                return tuple(element.coerce(item) for item in value)
            except TypeMismatch as error:
                raise TypeMismatch(f"expected {self.name}, got {_show(value)} ({error})") from None
        if self.tuple_size:
            if not isinstance(value, (list, tuple)) or len(value) != self.tuple_size:
                raise TypeMismatch(f"expected {self.name}, got {_show(value)}")
            scalar = parse_type(self.base)
            try:
                return tuple(scalar.coerce(item) for item in value)
            except TypeMismatch:
                raise TypeMismatch(f"expected {self.name}, got {_show(value)}") from None
        return _coerce_scalar(SCALAR_KINDS[self.base], self.name, value)


def _show(value) -> str:
    import json

    try:
        text = json.dumps(value)
    except (TypeError, ValueError):
        text = repr(value)
    return text if len(text) <= 60 else text[:57] + "..."


def _coerce_scalar(kind: str, name: str, value):
    if kind == "bool":
        if isinstance(value, bool):
            return value
    elif kind in ("int", "uint"):
        if isinstance(value, float) and value.is_integer():
            value = int(value)
        if isinstance(value, int) and not isinstance(value, bool):
            low, high = INTEGER_RANGES.get(name, (None, None))
            if low is not None and high is not None and not low <= value <= high:
                raise TypeMismatch(f"expected {name} ({low} to {high}), got {_show(value)}")
            return value
    elif kind == "real":
        if isinstance(value, int) and not isinstance(value, bool):
            try:
                value = float(value)
            except OverflowError:
                raise TypeMismatch(f"expected {name}, got a number too large for it") from None
        if isinstance(value, str) and value.lower() in ("nan", "inf", "-inf", "infinity", "-infinity"):
            value = float(value)
        if isinstance(value, float):
            limit = REAL_LIMITS.get(name)
            if limit is not None and math.isfinite(value) and abs(value) > limit:
                raise TypeMismatch(f"expected {name} (magnitude up to {limit:g}), got {_show(value)}")
            return value
    elif kind == "str":
        if isinstance(value, str):
            if name == "path" and value and not value.startswith("/"):
                raise TypeMismatch(f"expected an absolute prim path (starting with '/'), got {_show(value)}")
            return value
    raise TypeMismatch(f"expected {name}, got {_show(value)}")


def _coerce_target(value, name: str):
    paths = [value] if isinstance(value, str) else value
    if not isinstance(paths, (list, tuple)) or not all(isinstance(p, str) for p in paths):
        raise TypeMismatch(f"expected {name} (a prim path or a list of prim paths), got {_show(value)}")
    for path in paths:
        if not path.startswith("/"):
            raise TypeMismatch(f"expected {name} (absolute prim paths), got {_show(value)}")
    return tuple(paths)


def _freeze(value):
    if isinstance(value, list):
        return tuple(_freeze(v) for v in value)
    return value


@lru_cache(maxsize=None)
def parse_type(name: str) -> AttrType:
    """Parse a type name; raise ValueError for an unknown one."""
    if name in ("execution", "target", "any", "bundle"):
        return AttrType(name, name, 0, False)
    match = _TYPE_PATTERN.match(name)
    if not match:
        raise ValueError(f"unknown attribute type {name!r}")
    base, size, array = match["base"], match["n"], bool(match["array"])
    if base in TUPLE_ROLES:
        if not size:
            raise ValueError(f"unknown attribute type {name!r}")
        base = TUPLE_ROLES[base]
    if base not in SCALAR_KINDS:
        raise ValueError(f"unknown attribute type {name!r}")
    tuple_size = int(size) if size else 0
    if tuple_size and (base not in TUPLE_BASES or tuple_size not in (2, 3, 4, 9, 16)):
        raise ValueError(f"unknown attribute type {name!r}")
    return AttrType(name, base, tuple_size, array)


def element_type(array_type: AttrType) -> AttrType:
    """The element type of an array type (``double[3][]`` -> ``double[3]``)."""
    return parse_type(array_type.name[:-2])


def can_connect(source: AttrType, destination: AttrType) -> bool:
    """Whether an output of type *source* may feed an input of type *destination*.

    Execution only connects to execution, bundle only to bundle. ``any`` accepts and feeds every data
    type. Numeric scalars widen into each other (int -> double, float <-> double)
    when the tuple size and array-ness agree; token and string interconvert.
    """
    if source.is_execution or destination.is_execution:
        return source.is_execution and destination.is_execution
    if source.is_bundle or destination.is_bundle:
        return source.is_bundle and destination.is_bundle
    if source.is_any or destination.is_any:
        return True
    if source.is_target or destination.is_target:
        return source.is_target == destination.is_target or (
            destination.is_target and SCALAR_KINDS.get(source.base) == "str")
    if source.tuple_size != destination.tuple_size or source.is_array != destination.is_array:
        return False
    source_kind, destination_kind = SCALAR_KINDS[source.base], SCALAR_KINDS[destination.base]
    if source_kind == destination_kind:
        return True
    numeric = ("int", "uint", "real")
    return source_kind in numeric and destination_kind in numeric and destination_kind != "bool"


MAX_VALUE_DEPTH = 16   # nested tuples in one value; double[3][] is 2, a value fed back into itself grows by 1 a tick


def nesting_exceeds(value, limit: int = MAX_VALUE_DEPTH) -> bool:
    """Whether tuples nest deeper than *limit* in *value* (each shared tuple visited once: linear time)."""
    pending, seen = [(value, 0)], set()
    while pending:
        item, depth = pending.pop()
        if isinstance(item, tuple) and id(item) not in seen:
            if depth >= limit:
                return True
            seen.add(id(item))
            pending.extend((child, depth + 1) for child in item)
    return False

