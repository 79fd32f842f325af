"""Run traces: what happened on every tick, as JSON Lines (format in docs/trace.md).

A trace is written while a graph runs (``graphflow run GRAPH --trace FILE``) so a
run can be read, plotted (``graphflow plot``) and compared with another
(``graphflow trace diff``) afterwards; ``graphflow.observe.recorder`` writes it, this
module samples what it holds, reads it back and compares. Every tick record holds only what changed
on that tick, so the file stays small and two runs differ exactly where their
behaviour does. Nothing depends on the wall clock and floats are written by
``repr``: the same run gives a byte-identical file.
"""
from __future__ import annotations

import json
import os
import platform
import sys
from dataclasses import dataclass
from importlib import metadata
from pathlib import Path
from typing import Any, Iterator, NamedTuple

from graphflow import __version__
from graphflow.bundles import Bundle
from graphflow.errors import BadInput
from graphflow.gripper.component import STATUS_TOKENS

TRACE_FORMAT = "graphflow-trace"
TRACE_VERSION = 2            # 2 added the scene section (graphflow.observe.trace_scene); 1 is still read
READABLE_VERSIONS = (1, 2)
PHASE_OUTPUT = "eventName"   # an output with this name carries a controller's phase (PickPlaceController)

class TraceError(BadInput):
    """A trace file that cannot be read (missing, not JSON Lines, no header)."""


def to_json_value(value: Any) -> Any:
    """A plain JSON value for an attribute value: tuples and arrays become lists, enums their names.

    A bundle becomes ``{"attributes": {name: value, ...}}`` in its attribute order, with
    ``"children": [...]`` when it has child bundles (one per prim of a ReadPrims bundle)."""
    if value is None or isinstance(value, (bool, int, float, str)):
        return value
    if isinstance(value, Bundle):
        data: dict[str, Any] = {"attributes": {a.name: to_json_value(a.value) for a in value.attributes}}
        if value.children:
            data["children"] = [to_json_value(child) for child in value.children]
        return data
    if hasattr(value, "tolist"):       # numpy arrays and scalars
        return to_json_value(value.tolist())
    if isinstance(value, (tuple, list)):
        return [to_json_value(item) for item in value]
    if isinstance(value, dict):
        return {str(key): to_json_value(item) for key, item in value.items()}
    if hasattr(value, "name") and hasattr(value, "value"):   # enums
        return value.name
    return f"<{type(value).__name__}>"   # never repr(): it may hold a memory address


def dumps_record(record: dict) -> str:
    """One trace line: compact separators, keys in insertion order, floats as repr."""
    return json.dumps(record, separators=(",", ":"), ensure_ascii=False)


def loaded_versions() -> dict[str, str]:
    """graphflow and Python always; pybullet and usd-core only if this run loaded them."""
    versions = {"graphflow": __version__, "python": platform.python_version()}
    for module, distribution, key in (("pybullet", "pybullet", "pybullet"), ("pxr", "usd-core", "usd")):
        if module in sys.modules:
            try:
                versions[key] = metadata.version(distribution)
            except metadata.PackageNotFoundError:
                versions[key] = "unknown"
    return versions


def phase_outputs(compiled) -> list[str]:
    """``node.eventName`` keys of nodes whose outputs include a phase name (controllers)."""
    return [f"{node.name}.{PHASE_OUTPUT}" for node in compiled.nodes
            if node.spec.attribute(f"outputs:{PHASE_OUTPUT}") is not None]


def surface_gripper_manager(world):
    """The world's surface-gripper manager service, or None when no node made one."""
    from graphflow.gripper.manager import SurfaceGripperManager

    return world.services.get(SurfaceGripperManager)


class GripperSample(NamedTuple):
    """One gripper as seen after a tick: status, gripped objects, holding force, held height, reason.

    A tuple: a recorder keeps its fields in this order (``gripper_fields``, ``TraceRecorder.on_tick``)."""

    status: str
    gripped: tuple[str, ...]
    force: float | None
    held_z: float | None
    reason: str = ""      # why the last close failed or grip ended (SurfaceGripperComponent.reason)

    def fields(self) -> dict:
        return {"status": self.status, "gripped": list(self.gripped), "force": self.force, "heldZ": self.held_z,
                "reason": self.reason}


def sample_grippers(world, manager=None) -> dict[str, GripperSample]:
    """Every surface gripper of the world: status, gripped objects, constraint force (N), held object's z (m).

    *manager*: the world's gripper manager, when the caller has looked it up already."""
    if manager is None:
        manager = surface_gripper_manager(world)
    if manager is None:
        return {}
    components = getattr(manager, "components", {})
    return {path: GripperSample(*gripper_fields(world, components[path])) for path in sorted(components)}


def gripper_fields(world, component) -> tuple:
    """One gripper's sample in ``GripperSample``'s field order (the recorder keeps them flat)."""
    status, reason = STATUS_TOKENS[component.status], component.reason
    gripped = tuple(component.gripped_objects()) if component.handles else ()
    if not gripped:
        return status, (), None, None, reason
    return status, gripped, _holding_force(component), float(world.prim_pose(gripped[0])[0][2]), reason


def used_grippers(simulation) -> list[str]:
    """The surface grippers the graph uses, as the run starts.

    A gripper prim of the stage counts when a node input or a check names it (a packaged gripper the
    graph never touches does not); a LegacySurfaceGripper node's own gripper counts from the start, at
    the path it will author on its first execIn (the next free ``SurfaceGripper`` under its end
    effector); a gripper a node already made counts. Grippers made later appear in tick records.
    """
    world = simulation.world
    description = getattr(world, "description", None)
    on_stage = {gripper.path for gripper in getattr(description, "surface_grippers", ())}
    document = simulation.document
    named = {path for node in document.nodes for value in node.inputs.values() for path in _texts(value)}
    named |= {check["gripper"] for check in document.checks if isinstance(check.get("gripper"), str)}
    used = (on_stage & named) | set(sample_grippers(world))
    stage = getattr(world, "stage", None)
    planned: set[str] = set()
    for node in simulation.instance.compiled.nodes:
        if node.spec.id == LEGACY_GRIPPER and stage is not None:
            for end_effector in _texts(dict(document.node(node.name).inputs).get("endEffectorPrim", ())):
                path = _next_free(stage, end_effector.rstrip("/") + "/SurfaceGripper", planned)
                planned.add(path)
    return sorted(used | planned)


LEGACY_GRIPPER = "graphflow.LegacySurfaceGripper"


def _texts(value) -> list[str]:
    if isinstance(value, str):
        return [value]
    return [item for item in value if isinstance(item, str)] if isinstance(value, (list, tuple)) else []


def _next_free(stage, path: str, taken: set[str]) -> str:
    """``usd_schema.next_free_path`` that also skips the paths other legacy nodes will take."""
    candidate, index = path, 0
    while stage.GetPrimAtPath(candidate) or candidate in taken:
        index += 1
        candidate = f"{path}_{index:02d}"
    return candidate


def _holding_force(component) -> float | None:
    """The largest force an attachment of this gripper carries, as its break limits see it (N)."""
    magnitudes = [float(component.checked_force(handle)) for handle in component.handles.values()]
    return max(magnitudes) if magnitudes else None


# ---------------------------------------------------------------- reading

@dataclass(frozen=True)
class Trace:
    """A trace read back: the header and the tick records, in file order."""

    header: dict
    ticks: list[dict]

    def series(self, key: str) -> Iterator[tuple[float, Any]]:
        """(t, value) each time an output (``node.name``) changed."""
        for record in self.ticks:
            outputs = record.get("outputs", {})
            if key in outputs:
                yield record["t"], outputs[key]

    def gripper_series(self, path: str, field: str) -> list[tuple[float, Any]]:
        """(t, value) of one gripper field on every tick, carrying the last change forward."""
        current, points = None, []
        for record in self.ticks:
            delta = record.get("grippers", {}).get(path, {})
            if field in delta:
                current = delta[field]
            points.append((record["t"], current))
        return points

    @property
    def gripper_paths(self) -> list[str]:
        paths = set(self.header.get("grippers", []))
        for record in self.ticks:
            paths.update(record.get("grippers", {}))
        return sorted(paths)


def read_trace(path: str | Path) -> Trace:
    """Parse a trace file; raise TraceError naming the line when it is not a trace."""
    from graphflow.files import FileProblem, read_text

    try:
        text = read_text(path)   # regular files only: never reads /dev/zero forever
    except FileProblem as error:
        raise TraceError(str(error)) from None
    return parse_trace(text, path)


def parse_trace(text: str, path: str | Path = "<trace>") -> Trace:
    """A trace from its text (a file's, or one recorded in memory); TraceError naming the line."""
    from graphflow.files import FileProblem, loads_strict

    lines = text.splitlines()
    records = []
    for number, line in enumerate(lines, start=1):
        try:
            record = loads_strict(line, f"{path}: line {number}", non_finite=True)   # NaN, Infinity as written
        except FileProblem as error:
            if number == 1:
                raise TraceError(f"{path}: not a graphflow trace (line 1 is not a JSON header: {error.reason})") from None
            raise TraceError(f"{path}: line {number} is not JSON: {error.reason}") from None
        if not isinstance(record, dict):
            raise TraceError(f"{path}: line {number} is not a JSON object")
        if number > 1 and not isinstance(record.get("tick"), int):
            raise TraceError(f"{path}: line {number} has no tick number")
        records.append(record)
    if not records or records[0].get("format") != TRACE_FORMAT:
        raise TraceError(f"{path}: not a graphflow trace (the first line must be a header with format {TRACE_FORMAT!r})")
    if records[0].get("version") not in READABLE_VERSIONS:
        raise TraceError(f"{path}: trace version {records[0].get('version')!r} is not supported "
                         f"(this reads {', '.join(map(str, READABLE_VERSIONS))})")
    return Trace(records[0], records[1:])


# ---------------------------------------------------------------- comparing

def same_path_text(path):
    """One spelling per path, so ``graphs/x.json`` and ``./graphs/x.json`` name the same graph in traces."""
    return os.path.normpath(path).replace(os.sep, "/") if isinstance(path, str) and path else path


HEADER_FIELDS_IGNORED_BY_DIFF = ("versions",)   # the same run on another machine is still the same run


@dataclass(frozen=True)
class Difference:
    """Where two traces first part: the tick (0 for the header), the field path and both values."""

    tick: int
    time: float | None
    field: str
    left: Any
    right: Any

    def describe(self, left_name: str = "A", right_name: str = "B") -> str:
        where = "header" if self.tick == 0 else f"tick {self.tick}" + (f" (t = {self.time!r} s)" if self.time is not None else "")
        return (f"traces differ at {where}, field {self.field}:\n"
                f"  {left_name}: {_shown(self.left)}\n  {right_name}: {_shown(self.right)}")


_ABSENT = "<absent>"


def _shown(value) -> str:
    return value if value is _ABSENT else json.dumps(value)


def first_difference(left: Trace, right: Trace) -> Difference | None:
    """The first differing field: header (except versions), then tick by tick, fields in file order."""
    left_header, right_header = ({key: same_path_text(value) if key == "graph" else value
                                  for key, value in trace.header.items() if key not in HEADER_FIELDS_IGNORED_BY_DIFF}
                                 for trace in (left, right))
    found = _first_field(left_header, right_header, "")
    if found is not None:
        return Difference(0, None, found[0], found[1], found[2])
    for left_record, right_record in zip(left.ticks, right.ticks):
        found = _first_field(left_record, right_record, "")
        if found is not None:
            return Difference(left_record.get("tick", 0), left_record.get("t"), found[0], found[1], found[2])
    if len(left.ticks) != len(right.ticks):
        shorter = min(len(left.ticks), len(right.ticks))
        extra = (left.ticks if len(left.ticks) > shorter else right.ticks)[shorter]
        left_tick = left.ticks[shorter]["tick"] if len(left.ticks) > shorter else _ABSENT
        right_tick = right.ticks[shorter]["tick"] if len(right.ticks) > shorter else _ABSENT
        return Difference(extra["tick"], extra.get("t"), "tick", left_tick, right_tick)
    return None


def _first_field(left: Any, right: Any, path: str) -> tuple[str, Any, Any] | None:
    if isinstance(left, dict) and isinstance(right, dict):
        keys = list(left) + [key for key in right if key not in left]
        for key in keys:
            child = f"{path}.{key}" if path else key
            if key not in left or key not in right:
                return child, left.get(key, _ABSENT), right.get(key, _ABSENT)
            found = _first_field(left[key], right[key], child)
            if found is not None:
                return found
        return None
    if isinstance(left, list) and isinstance(right, list):
        for index, (a, b) in enumerate(zip(left, right)):
            found = _first_field(a, b, f"{path}[{index}]")
            if found is not None:
                return found
        if len(left) != len(right):
            index = min(len(left), len(right))
            return (f"{path}[{index}]", left[index] if index < len(left) else _ABSENT,
                    right[index] if index < len(right) else _ABSENT)
        return None
    if type(left) is not type(right) or (left != right and dumps_record(left) != dumps_record(right)):
        return path, left, right
    return None
