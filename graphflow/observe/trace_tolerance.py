"""Golden traces compared with tolerances: floats within per-field bounds, everything discrete exact.

``graphflow trace diff A B`` is exact: a trace written on another machine (another numpy or OpenBLAS,
another libm) differs in the last bits of its floats and fails it. ``trace diff --tolerance`` and the
``matchesTrace`` check compare the *state* of both runs tick by tick instead (a trace records only what
changed, so each side's outputs and gripper fields are carried forward) and allow each float a bound by
what it measures: positions (m), angles (rad, quaternion components), forces (N) and other values, or a
bound given for one ``node.port`` / ``grippers.PATH.field``. Exec pulses, phases, statuses, gripped
objects, strings, integers, log lines and the tick clock must match exactly. Defaults: docs/trace.md.
"""
from __future__ import annotations

import json
import math
from dataclasses import dataclass, field
from typing import Any, Mapping

from graphflow.errors import BadInput
from graphflow.observe.trace import Trace, same_path_text

HEADER_FIELDS_IGNORED = ("graph", "description", "versions")   # where and how it ran, not what happened
EXACT_GRIPPER_FIELDS = ("status", "gripped", "reason")
KINDS = ("positions", "angles", "forces", "values")


class ToleranceError(BadInput):
    """A tolerance value or file that cannot be used (one line naming it)."""


@dataclass(frozen=True)
class Bound:
    """|a - b| <= absolute + relative * max(|a|, |b|)."""

    absolute: float
    relative: float = 0.0

    def allows(self, left: float, right: float) -> bool:
        if math.isnan(left) or math.isnan(right):
            return math.isnan(left) and math.isnan(right)
        if math.isinf(left) or math.isinf(right):
            return left == right
        return abs(left - right) <= self.absolute + self.relative * max(abs(left), abs(right))

    def text(self, unit: str) -> str:
        relative = f" + {self.relative:g} x value" if self.relative else ""
        return f"{self.absolute:g}{unit}{relative}"


UNITS = {"positions": " m", "angles": " rad", "forces": " N", "values": ""}

# Measured on the tuned pick-and-place (docs/trace.md): one ulp added to every IK solution moves positions by
# at most 4.2e-9 m and quaternion components by 4.6e-7; a cube start 6e-8 m off moves positions by 6e-8 m;
# a 1 % heavier cube moves the cube's position by 7.8e-7 m and its quaternion by 7.7e-6. The defaults sit between.
# A stiff hold's force is a solver result: one ulp moves the 3.3 mN hold force by 2.7e-6 N, a 1 % heavier cube by 3e-5 N.
DEFAULT_BOUNDS = {"positions": Bound(1e-7), "angles": Bound(2e-6),
                  "forces": Bound(1e-4, 1e-3), "values": Bound(1e-9, 1e-9)}


@dataclass(frozen=True)
class Tolerances:
    """A bound per kind of quantity, and bounds for named fields (``node.port``, ``grippers.PATH.field``)."""

    kinds: Mapping[str, Bound] = field(default_factory=lambda: dict(DEFAULT_BOUNDS))
    fields: Mapping[str, Bound] = field(default_factory=dict)

    def bound(self, key: str, kind: str) -> tuple[Bound, str]:
        """The bound for a field and what it is called in a report."""
        if key in self.fields:
            return self.fields[key], f"{key} tolerance"
        return self.kinds[kind], f"{kind} tolerance"


def _bound(value: Any, where: str) -> Bound:
    if isinstance(value, (int, float)) and not isinstance(value, bool) and math.isfinite(value) and value >= 0:
        return Bound(float(value))
    if isinstance(value, dict) and set(value) <= {"absolute", "relative"} and value:
        parts = [value.get("absolute", 0.0), value.get("relative", 0.0)]
        if all(isinstance(p, (int, float)) and not isinstance(p, bool) and math.isfinite(p) and p >= 0 for p in parts):
            return Bound(float(parts[0]), float(parts[1]))
    raise ToleranceError(f"{where}: expected a non-negative number or {{\"absolute\": A, \"relative\": R}}, "
                         f"got {json.dumps(value)}")


def tolerances_from(spec: Any, source: str) -> Tolerances:
    """Tolerances from a number (every float's absolute bound) or a mapping of kinds and ``fields``."""
    if spec is None:
        return Tolerances()
    if not isinstance(spec, dict):
        bound = _bound(spec, source)
        return Tolerances({kind: bound for kind in KINDS})
    unknown = sorted(set(spec) - {*KINDS, "fields"})
    if unknown:
        raise ToleranceError(f"{source}: unknown key {unknown[0]!r} (expected {', '.join(KINDS)} or fields)")
    kinds = dict(DEFAULT_BOUNDS)
    kinds.update({kind: _bound(spec[kind], f"{source}: {kind}") for kind in KINDS if kind in spec})
    named = spec.get("fields", {})
    if not isinstance(named, dict):
        raise ToleranceError(f"{source}: fields: expected an object of field: tolerance")
    return Tolerances(kinds, {key: _bound(value, f"{source}: fields.{key}") for key, value in named.items()})


def read_tolerances(text: str | None, base_dir=None) -> Tolerances:
    """``--tolerance`` (None: the defaults), a number, or a JSON file of tolerances (relative to *base_dir*)."""
    from pathlib import Path

    from graphflow.files import FileProblem, read_json

    if text is None:
        return Tolerances()
    try:
        return tolerances_from(float(text), f"--tolerance {text}")
    except ValueError:
        pass
    path = Path(base_dir) / text if base_dir is not None else Path(text)
    try:
        data = read_json(path)
    except FileProblem as error:
        raise ToleranceError(str(error)) from None
    return tolerances_from(data, str(path))


# ---------------------------------------------------------------- what a field measures

def _port_kind(spec_type: str, description: str) -> str:
    """positions, angles, forces or values, from the port's type and the unit its description names."""
    text = f" {description} ".replace("(", " ").replace(")", " ").replace(",", " ")
    if spec_type.startswith("quat") or " rad" in text or "radian" in text or "orientation" in text.lower():
        return "angles"
    if " N " in text or " N m" in text or "force" in text.lower():
        return "forces"
    if " m " in text or " m/s" in text:
        return "positions"
    return "values"


def output_kinds(header: Mapping[str, Any]) -> dict[str, str]:
    """``node.port`` -> kind for every output the trace's header lists (node types from the registry)."""
    from graphflow.registry import default_registry

    registry = default_registry()
    kinds = {}
    for key in header.get("outputs", {}):
        node, _, port = key.partition(".")
        node_type = registry.get(header.get("nodes", {}).get(node, ""))
        attribute = node_type.spec.attribute(f"outputs:{port}") if node_type is not None else None
        kinds[key] = _port_kind(attribute.type, attribute.description) if attribute is not None else "values"
    return kinds


GRIPPER_KINDS = {"force": "forces", "heldZ": "positions"}


# ---------------------------------------------------------------- comparing

@dataclass(frozen=True)
class Divergence:
    """Where two runs first part beyond tolerance, and what the first run was doing then."""

    tick: int
    time: float | None
    field: str
    left: Any
    right: Any
    bound: str = ""          # "positions tolerance 1e-07 m" when a float was out of bounds; "" when exact
    phase: str = ""
    grippers: tuple[str, ...] = ()

    def describe(self, left_name: str = "A", right_name: str = "B") -> str:
        where = "header" if self.tick == 0 else f"tick {self.tick}" + (f" (t = {self.time!r} s)" if self.time is not None else "")
        how = f"beyond {self.bound}" if self.bound else "exact field"
        lines = [f"traces differ at {where}, field {self.field} ({how}):",
                 f"  {left_name}: {_shown(self.left)}", f"  {right_name}: {_shown(self.right)}"]
        if isinstance(self.left, (int, float)) and isinstance(self.right, (int, float)) and self.bound:
            lines.append(f"  difference: {abs(self.left - self.right):.6g}")
        if self.phase:
            lines.append(f"  phase: {self.phase}")
        lines += [f"  gripper {text}" for text in self.grippers]
        return "\n".join(lines)

    def one_line(self) -> str:
        where = f"tick {self.tick}" + (f" (t = {self.time:.3f} s)" if self.time is not None else "")
        context = "".join(f", {part}" for part in ([f"phase {self.phase}"] if self.phase else []) + list(self.grippers))
        how = f", beyond {self.bound}" if self.bound else ""
        return f"{self.field} at {where}: {_shown(self.right)} vs golden {_shown(self.left)}{how}{context}"


_ABSENT = "<absent>"


def _shown(value) -> str:
    return value if value is _ABSENT else json.dumps(value)


def _numbers_differ(left, right, bound: Bound) -> tuple[str, Any, Any] | None:
    """('' path suffix, a, b) of the first component beyond *bound*, comparing numbers and lists of them."""
    if isinstance(left, float) or isinstance(right, float):
        if isinstance(left, (int, float)) and isinstance(right, (int, float)) and not isinstance(left, bool) \
                and not isinstance(right, bool):
            return None if bound.allows(float(left), float(right)) else ("", left, right)
        return "", left, right
    if isinstance(left, list) and isinstance(right, list):
        for index, (a, b) in enumerate(zip(left, right)):
            found = _numbers_differ(a, b, bound)
            if found is not None:
                return f"[{index}]{found[0]}", found[1], found[2]
        if len(left) != len(right):
            index = min(len(left), len(right))
            return (f"[{index}]", left[index] if index < len(left) else _ABSENT,
                    right[index] if index < len(right) else _ABSENT)
        return None
    if isinstance(left, dict) and isinstance(right, dict):
        for key in list(left) + [k for k in right if k not in left]:
            if key not in left or key not in right:
                return f".{key}", left.get(key, _ABSENT), right.get(key, _ABSENT)
            found = _numbers_differ(left[key], right[key], bound)
            if found is not None:
                return f".{key}{found[0]}", found[1], found[2]
        return None
    if type(left) is not type(right) or left != right:
        return "", left, right
    return None


class _State:
    """One run's outputs and gripper fields as of the current tick (changes carried forward)."""

    def __init__(self, trace: Trace):
        self.outputs = dict(trace.header.get("outputs", {}))
        self.grippers: dict[str, dict] = {}
        self.phases = list(trace.header.get("phases", []))

    def apply(self, record: Mapping[str, Any]) -> set[str]:
        changed = set()
        for key, value in record.get("outputs", {}).items():
            self.outputs[key] = value
            changed.add(f"outputs.{key}")
        for path, delta in record.get("grippers", {}).items():
            self.grippers.setdefault(path, {}).update(delta)
            changed.update(f"grippers.{path}.{name}" for name in delta)
        return changed

    def value(self, key: str):
        if key.startswith("outputs."):
            return self.outputs.get(key[len("outputs."):], _ABSENT)
        path, _, name = key[len("grippers."):].rpartition(".")
        return self.grippers.get(path, {}).get(name, _ABSENT)

    def context(self) -> tuple[str, tuple[str, ...]]:
        phase = " ".join(str(self.outputs.get(key)) for key in self.phases if self.outputs.get(key) not in (None, ""))
        grippers = []
        for path, fields in sorted(self.grippers.items()):
            reason = fields.get("reason") or ""
            grippers.append(f"{path} {fields.get('status', '?')}" + (f" ({reason})" if reason else ""))
        return phase, tuple(grippers)


def tolerant_difference(left: Trace, right: Trace, tolerances: Tolerances = Tolerances()) -> Divergence | None:
    """The first field where *right* leaves *left* by more than its tolerance (or differs in an exact field)."""
    headers = [{key: same_path_text(value) if key == "graph" else value for key, value in trace.header.items()
                if key not in HEADER_FIELDS_IGNORED and key != "outputs"} for trace in (left, right)]
    for key in list(headers[0]) + [k for k in headers[1] if k not in headers[0]]:
        if headers[0].get(key, _ABSENT) != headers[1].get(key, _ABSENT):
            return Divergence(0, None, key, headers[0].get(key, _ABSENT), headers[1].get(key, _ABSENT))
    kinds = output_kinds(left.header)
    states = _State(left), _State(right)
    found = _compare_fields(states, set(f"outputs.{key}" for key in states[0].outputs) |
                            set(f"outputs.{key}" for key in states[1].outputs), kinds, tolerances)
    if found is not None:
        return Divergence(0, None, *found, phase="", grippers=())
    for left_record, right_record in zip(left.ticks, right.ticks):
        tick, time = left_record.get("tick", 0), left_record.get("t")
        for key in ("tick", "t", "pulses", "log"):
            if left_record.get(key, []) != right_record.get(key, []):
                return _at(states[0], tick, time, key, left_record.get(key, []), right_record.get(key, []))
        topics = _numbers_differ(left_record.get("topics", []), right_record.get("topics", []), tolerances.kinds["values"])
        if topics is not None:
            return _at(states[0], tick, time, f"topics{topics[0]}", topics[1], topics[2], "values tolerance")
        changed = states[0].apply(left_record) | states[1].apply(right_record)
        found = _compare_fields(states, changed, kinds, tolerances)
        if found is not None:
            return _at(states[0], tick, time, *found)
    if len(left.ticks) != len(right.ticks):
        shorter = min(len(left.ticks), len(right.ticks))
        extra = (left.ticks if len(left.ticks) > shorter else right.ticks)[shorter]
        return _at(states[0], extra["tick"], extra.get("t"), "tick",
                   left.ticks[shorter]["tick"] if len(left.ticks) > shorter else _ABSENT,
                   right.ticks[shorter]["tick"] if len(right.ticks) > shorter else _ABSENT)
    return None


def _at(state: _State, tick: int, time, name: str, left, right, bound: str = "") -> Divergence:
    phase, grippers = state.context()
    return Divergence(tick, time, name, left, right, bound, phase, grippers)


def _compare_fields(states, keys, kinds: Mapping[str, str], tolerances: Tolerances) -> tuple[str, Any, Any, str] | None:
    """(field, left, right, bound text) of the first field (sorted) that differs beyond its tolerance."""
    for key in sorted(keys):
        left, right = states[0].value(key), states[1].value(key)
        if key.startswith("outputs."):
            name = key[len("outputs."):]
            kind = kinds.get(name, "values")
        else:
            name = key
            gripper_kind = GRIPPER_KINDS.get(key.rpartition(".")[2])
            if gripper_kind is None:   # status, gripped, reason: exact
                if left != right:
                    return key, left, right, ""
                continue
            kind = gripper_kind
        bound, label = tolerances.bound(name, kind)
        found = _numbers_differ(left, right, bound)
        if found is not None:
            exact = not isinstance(found[1], float) and not isinstance(found[2], float)
            return key + found[0], found[1], found[2], "" if exact else f"{label} {bound.text(UNITS[kind])}"
    return None

