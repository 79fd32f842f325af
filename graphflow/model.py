"""The graph document as data: nodes, connections, variables, settings, and the problems found in one.

Immutable definitions shared by the loader (``graphflow.document``), the
compiler and the executor; this module imports nothing of theirs, so they can
all depend on it without a cycle.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path
from types import MappingProxyType
from typing import Any, Mapping

from graphflow.errors import BadInput
from graphflow.files import one_line

FORMAT_NAME = "graphflow"
FORMAT_VERSION = (1, 0)


@dataclass(frozen=True)
class Problem:
    """One thing wrong with a graph file."""

    file: str
    message: str
    node: str | None = None
    attribute: str | None = None
    kind: str = "input"  # how the attribute is named in the message: input, output, connection, variable
    path: tuple = ()     # where in the JSON a schema problem is (("nodes", 3, "name")); () for the others

    def __str__(self) -> str:
        locator = []
        if self.node is not None:
            locator.append(f"node '{self.node}'")
        if self.attribute is not None:
            locator.append(f"{self.kind} '{self.attribute}'")
        if locator:
            return one_line(f"{self.file}: {' '.join(locator)}: {self.message}")
        return one_line(f"{self.file}: {self.message}")


class GraphError(BadInput):
    """A graph file could not be loaded; ``problems`` lists every reason."""

    def __init__(self, problems: list[Problem]):
        self.problems = problems
        super().__init__("\n".join(str(p) for p in problems))


def frozen_mapping(mapping: Mapping) -> Mapping:
    return MappingProxyType(dict(mapping))


@dataclass(frozen=True)
class NodeDoc:
    name: str
    type: str
    type_version: int | None = None
    inputs: Mapping[str, Any] = field(default_factory=dict)
    description: str = ""


@dataclass(frozen=True)
class Connection:
    src_node: str
    src_attr: str   # "outputs:x"
    dst_node: str
    dst_attr: str   # "inputs:y"

    @property
    def src(self) -> str:
        return f"{self.src_node}.{self.src_attr}"

    @property
    def dst(self) -> str:
        return f"{self.dst_node}.{self.dst_attr}"


@dataclass(frozen=True)
class Variable:
    name: str
    type: str
    default: Any = None
    description: str = ""


@dataclass(frozen=True)
class GraphDocument:
    """A graph as authored; no runtime state."""

    nodes: tuple[NodeDoc, ...]
    connections: tuple[Connection, ...] = ()
    variables: tuple[Variable, ...] = ()
    settings: Mapping[str, Any] = field(default_factory=dict)
    description: str = ""
    ui: Mapping[str, Any] = field(default_factory=dict)
    format_version: tuple[int, int] = FORMAT_VERSION
    source: str = "<graph>"   # the file it came from, for messages and relative stage paths
    checks: tuple[Mapping[str, Any], ...] = ()   # what must be true of a run (graphflow.verdicts.checks, docs/checks.md)
    scenario: Mapping[str, Any] = field(default_factory=dict)   # scripted inputs of a checked run (keys, gamepad)
    schema: str = ""   # the file's "$schema": the JSON Schema editors complete and check it with
    # its compiled graph per registry id, kept by graphflow.compiler.compile (derived, not part of the definition)
    _compiled: dict = field(default_factory=dict, init=False, repr=False, compare=False)

    def node(self, name: str) -> NodeDoc | None:
        return next((n for n in self.nodes if n.name == name), None)

    def missing_assets(self) -> dict[str, str]:
        """Node name -> the line naming its input whose prim's layer the importer could not open."""
        lines: dict[str, str] = {}
        for entry in self.settings.get("missingAssets", ()):
            lines.setdefault(entry["node"], f"input '{entry['input']}': {entry['message']}")
        return lines

    @property
    def base_dir(self) -> Path:
        return Path(self.source).resolve().parent if self.source != "<graph>" else Path.cwd()

    def to_json(self) -> dict:
        data: dict[str, Any] = {"format": FORMAT_NAME, "formatVersion": list(self.format_version)}
        if self.schema:
            data["$schema"] = self.schema
        if self.description:
            data["description"] = self.description
        if self.settings:
            data["settings"] = dict(self.settings)
        if self.variables:
            data["variables"] = [_variable_json(v) for v in self.variables]
        data["nodes"] = [_node_json(n) for n in self.nodes]
        if self.connections:
            data["connections"] = [{"src": c.src, "dst": c.dst} for c in self.connections]
        if self.ui:
            data["ui"] = dict(self.ui)
        if self.checks:
            data["checks"] = [dict(check) for check in self.checks]
        if self.scenario:
            data["scenario"] = dict(self.scenario)
        return data


def _node_json(node: NodeDoc) -> dict:
    entry: dict[str, Any] = {"name": node.name, "type": node.type}
    if node.type_version is not None:
        entry["typeVersion"] = node.type_version
    if node.inputs:
        entry["inputs"] = {name: _strict(value) for name, value in node.inputs.items()}
    if node.description:
        entry["description"] = node.description
    return entry


def _strict(value):
    """A value as strict JSON holds it: NaN and infinities as the strings "nan", "inf", "-inf" that load back."""
    if isinstance(value, float) and not math.isfinite(value):
        return "nan" if math.isnan(value) else ("inf" if value > 0 else "-inf")
    if isinstance(value, (tuple, list)):
        return [_strict(item) for item in value]
    return value


def _variable_json(variable: Variable) -> dict:
    entry: dict[str, Any] = {"name": variable.name, "type": variable.type}
    if variable.default is not None:
        entry["default"] = variable.default
    if variable.description:
        entry["description"] = variable.description
    return entry
