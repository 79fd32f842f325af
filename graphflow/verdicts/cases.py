"""Scenario tables: one graph and a table of named cases, each case one test item (docs/checks.md).

A table file (``"format": "graphflow-cases"``) names a graph with checks (``checks`` in the table add
to them, for every case) and lists cases. A case changes
the run with ``--set``-style overrides (``NODE.INPUT`` or ``/Prim.attribute``: node inputs and stage
edits), may script its own keys or gamepad and seed, and states what must happen: ``"expect": "pass"``
(every check holds) or ``{"fail": PATTERN}`` (the run fails and a failure line matches the regular
expression). ``graphflow test``, its JUnit report and the pytest plugin show each case by its name,
``TABLE::CASE``.
"""
from __future__ import annotations

import json
import re
import shlex
from dataclasses import dataclass, replace
from functools import lru_cache
from importlib import resources
from pathlib import Path
from typing import Any, Mapping

from graphflow.errors import BadInput
from graphflow.files import FileProblem, read_json

TABLE_FORMAT = "graphflow-cases"


class TableError(BadInput):
    """A table that cannot be used; one line naming the file and the case."""


@lru_cache(maxsize=1)
def table_schema() -> dict:
    return json.loads(resources.files("graphflow").joinpath("schema/cases.schema.json").read_text(encoding="utf-8"))


@dataclass(frozen=True)
class Case:
    """One row of a table: its name, overrides, scripted inputs, seed and expected outcome."""

    table: str
    graph: str
    name: str
    overrides: Mapping[str, Any]
    keys: Any = None
    gamepad: Any = None
    seed: int | None = None
    fail_pattern: str | None = None   # None: the case must pass
    checks: tuple = ()                # the table's checks, added to the graph's
    mouse: Any = None

    @property
    def item_name(self) -> str:
        return f"{self.table}::{self.name}"

    def edits(self) -> list:
        from graphflow.variants.overrides import Override

        return [Override(target, value, origin=f"{self.item_name}: set {target}={json.dumps(value)}")
                for target, value in self.overrides.items()]

    def rerun_command(self) -> str:
        """``graphflow run`` of this case alone (its verdict is the run's; the expectation is the table's)."""
        command = ["graphflow", "run", self.graph]
        for target, value in self.overrides.items():
            command += ["--set", f"{target}={json.dumps(value)}"]
        if self.seed is not None:
            command += ["--seed", str(self.seed)]
        for key in self.keys if isinstance(self.keys, list) else ():
            command += ["--key", key]
        if isinstance(self.keys, str):
            command += ["--keys", str(Path(self.table).parent / self.keys)]
        for pad in self.gamepad if isinstance(self.gamepad, list) else ():
            command += ["--pad", pad]
        if isinstance(self.gamepad, str):
            command += ["--gamepad", str(Path(self.table).parent / self.gamepad)]
        for event in self.mouse if isinstance(self.mouse, list) else ():
            command += ["--click", event]
        if isinstance(self.mouse, str):
            command += ["--mouse", str(Path(self.table).parent / self.mouse)]
        return shlex.join(command)


def is_table(data: Any) -> bool:
    return isinstance(data, dict) and data.get("format") == TABLE_FORMAT


def load_table(path: str | Path) -> list[Case]:
    """The cases of a table file, each checked against the graph (node overrides) before anything runs."""
    import jsonschema

    from graphflow.variants.overrides import OverrideError, apply_node_overrides

    source = str(path)
    try:
        data = read_json(path)
    except FileProblem as error:
        raise TableError(str(error)) from None
    errors = sorted(jsonschema.Draft202012Validator(table_schema()).iter_errors(data), key=lambda e: list(e.absolute_path))
    if errors:
        where = "/".join(str(p) for p in errors[0].absolute_path) or "document"
        raise TableError(f"{source}: {where}: {errors[0].message}")
    if data["formatVersion"][0] != 1:
        raise TableError(f"{source}: formatVersion {data['formatVersion']} is not supported (this runtime reads 1.x)")
    graph = str(Path(source).parent / data["graph"])
    checks = tuple(data.get("checks", ()))
    document = graph_with_checks(graph, checks)
    if not document.checks:
        raise TableError(f"{source}: graph {data['graph']} has no checks: a case's pass or fail would mean nothing")
    cases, names = [], set()
    for index, row in enumerate(data["cases"]):
        if row["name"] in names:
            raise TableError(f"{source}: cases/{index}: the name {row['name']!r} is used twice")
        names.add(row["name"])
        expect = row.get("expect", "pass")
        pattern = None if expect == "pass" else expect["fail"]
        if pattern is not None:
            try:
                re.compile(pattern)
            except re.error as error:
                raise TableError(f"{source}: case {row['name']!r}: expect.fail is not a regular expression: {error}") from None
        case = Case(source, graph, row["name"], dict(row.get("set", {})), row.get("keys"), row.get("gamepad"),
                    row.get("seed"), pattern, checks, row.get("mouse"))
        try:
            apply_node_overrides(document, [e for e in case.edits() if not e.on_stage])
        except OverrideError as error:
            raise TableError(str(error)) from None
        cases.append(case)
    return cases


def graph_with_checks(graph: str, checks: tuple):
    """The graph's document with the table's checks added (checked as the graph file itself would be)."""
    from graphflow.document import load_document, parse_document

    if not checks:
        return load_document(graph)
    data = read_json(graph)
    data["checks"] = [*data.get("checks", []), *checks]
    return parse_document(data, graph)


def run_case(case: Case, *, trace: str | Path | None = None):
    """Run one case (the one checked run with the case's variant and inputs); its verdict judges the expectation."""
    import contextlib

    from graphflow.inputs.gamepad import scripted_pad
    from graphflow.inputs.keyboard import scripted_keys
    from graphflow.inputs.mouse import scripted_mouse
    from graphflow.variants.overrides import make_variant
    from graphflow.verdicts.checked_run import CheckedRun, CollectedLog, ScriptedInputs

    document = graph_with_checks(case.graph, case.checks)
    inputs = ScriptedInputs.of_document(document)
    base = Path(case.table).parent
    for name, value, make in (("keys", case.keys, scripted_keys), ("pad", case.gamepad, scripted_pad),
                              ("mouse", case.mouse, scripted_mouse)):
        if value is not None:       # a case's input replaces the scenario's for that device; the rest stay
            inputs = replace(inputs, **{name: make(str(base / value)) if isinstance(value, str)
                                        else make(None, list(value))})
    checked = CheckedRun(document, source=case.item_name, variant=make_variant(document, case.edits()),
                         inputs=inputs, seed=case.seed)
    checked.verdict.expect_failure = ()
    checked.verdict.expect_pattern = case.fail_pattern
    checked.preflight()
    if checked.time_limit() is None:
        raise TableError(f"{case.graph}: no run limit: give settings.duration or a stopsBy check")
    checked.listeners.append(CollectedLog(checked.verdict.output))
    with contextlib.ExitStack() as closing:
        closing.callback(checked.close)
        simulation = checked.start()
        if trace is not None:
            from graphflow.observe.recorder import TraceRecorder

            stream = closing.enter_context(open(trace, "w", encoding="utf-8", newline="\n"))
            TraceRecorder(simulation, stream, graph=case.graph)
            checked.verdict.trace = str(trace)
        return checked.run()
