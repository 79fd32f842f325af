"""What the studio's editor asks the runtime: the palette, the problems of a graph, and saving it safely.

The browser never decides whether a graph is valid: every change is sent here and checked by the
same code ``graphflow validate`` runs (schema, compiler, stage and the prims it names), and the
problems come back with the node and attribute they name, for the page to mark. Saving writes the
canonical text through the atomic writer and is refused when the file changed on disk since it
was opened (its revision, a hash of its bytes) or when an invalid graph would replace a valid one.
"""
from __future__ import annotations

import difflib
import hashlib
import json
import re
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from graphflow.document import GraphDocument, dumps, parse_document
from graphflow.errors import BadInput
from graphflow.files import FileProblem, loads_strict, read_text, write_text
from graphflow.model import GraphError, Problem
from graphflow.registry import default_registry
from graphflow.studio.stage_prims import CHECK_FIELD_KINDS, port_kind
from graphflow.types import can_connect, parse_type


def revision(text: str | None) -> str | None:
    """The revision of a file's text (None: no file): what the editor opened, compared again on save."""
    return None if text is None else hashlib.sha256(text.encode("utf-8")).hexdigest()[:16]


def _port(attribute, prim_kind: str | None = None) -> dict:
    entry = {"name": attribute.name, "type": attribute.type, "description": attribute.description,
             "execution": attribute.is_execution, "optional": attribute.optional}
    if prim_kind is not None:
        entry["primKind"] = prim_kind   # the kind of stage prim it names: the page offers those in a picker
    if attribute.default is not None:
        entry["default"] = json.loads(json.dumps(attribute.default))
    for key, value in (("tokens", list(attribute.allowed_tokens)), ("minimum", attribute.minimum),
                       ("maximum", attribute.maximum), ("length", attribute.length)):
        if value:
            entry[key] = value
        elif value == 0:
            entry[key] = 0
    return entry


def palette() -> dict:
    """Every registered node type (id, UI name, categories, docs, ports) and which port types connect.

    ``connects[source][destination]`` is ``graphflow.types.can_connect`` over every port type the
    palette names, so the page offers exactly the connections the compiler accepts.
    """
    types: list[dict[str, Any]] = []
    for node_type in sorted(default_registry().types(), key=lambda node_type: node_type.spec.id):
        spec = node_type.spec
        types.append({"id": spec.id, "version": spec.version, "uiName": spec.ui_name or spec.id.rsplit(".", 1)[-1],
                      "categories": list(spec.categories), "description": spec.description,
                      "inputs": [_port(a, port_kind(spec.id, a)) for a in spec.inputs],
                      "outputs": [_port(a) for a in spec.outputs]})
    names = sorted({port["type"] for entry in types for group in ("inputs", "outputs") for port in entry[group]})
    parsed = {name: parse_type(name) for name in names}
    connects = {source: [destination for destination in names if can_connect(parsed[source], parsed[destination])]
                for source in names}
    return {"types": types, "connects": connects}


def document_forms() -> dict:
    """What the variables, checks and settings editors draw their fields from: the graph format's own schema."""
    from graphflow.document import json_schema

    properties = json_schema()["properties"]
    checks = {rule["if"]["properties"]["check"]["const"]: rule["then"]
              for rule in properties["checks"]["items"]["allOf"]}
    return {"settings": properties["settings"]["properties"], "seed": properties["scenario"]["properties"]["seed"],
            "variables": properties["variables"]["items"]["properties"], "checks": checks,
            "checkPrimKinds": CHECK_FIELD_KINDS}


CHECK_NUMBER = re.compile(r"checks\[(\d+)\]")


def problem_json(problem: Problem) -> dict:
    """A problem as the page marks it: on its node and attribute when it names them."""
    text = str(problem)
    prefix = f"{problem.file}: "
    message = text[len(prefix):] if text.startswith(prefix) else text
    path = list(problem.path)
    numbered = CHECK_NUMBER.match(message)
    if not path and numbered:   # a stage problem of a check says "checks[N]", counted from 1
        path = ["checks", int(numbered.group(1)) - 1]
    return {"message": message, "node": problem.node, "attribute": problem.attribute, "kind": problem.kind, "path": path}


def check(data, path: Path) -> tuple[list[Problem], GraphDocument | None]:
    """Every problem ``graphflow validate`` would report for *data* saved at *path*, and the document if none."""
    from graphflow.migration import migrate_on_load
    from graphflow.validate.preflight import document_problems

    try:
        document = migrate_on_load(parse_document(data, str(path)))
    except GraphError as error:
        return list(error.problems), None
    problems, _stage = document_problems(document)
    return problems, (document if not problems else None)


def canonical_text(data, document: GraphDocument | None) -> str:
    """The text saved: the compiler's canonical form when valid, the same layout (sorted keys, 2 spaces) when a draft."""
    if document is not None:
        return dumps(document)
    return json.dumps(data, indent=2, sort_keys=True, ensure_ascii=False) + "\n"


def read_graph(path: Path) -> dict:
    """An opened file: its text, parsed data (None when not JSON), revision and problems."""
    try:
        text = read_text(path)
    except FileProblem as error:
        raise BadInput(error.reason) from None
    try:
        data = loads_strict(text, str(path))
    except (FileProblem, ValueError) as error:
        return {"text": text, "data": None, "revision": revision(text), "problems": [{"message": str(error)}]}
    problems, _document = check(data, path)
    return {"text": text, "data": data, "revision": revision(text), "problems": [problem_json(p) for p in problems]}


def drawn_layout(data, path: Path) -> dict:
    """Where ``graphflow draw`` places each node ({name: [x, y]}), for a graph with no positions in ``ui``."""
    from graphflow.report.build import graph_layout

    try:
        document = parse_document(data, str(path))
    except GraphError:
        return {}
    return {node["name"]: [node["x"], node["y"]] for node in graph_layout(document)["nodes"]}


def watched_revision(path: Path, watched) -> dict:
    """What the page polls to reload and re-run: the graph's revision, and one of every other file the run reads.

    *watched* is the graph's ``graphflow.watching.WatchedFiles`` (the same files ``run --watch`` watches:
    stage, its local layers, scripted-input files), kept between polls so a stage is not reopened each time.
    """
    others = {name: state for name, state in watched.state().items() if name != str(path)}
    return {"revision": revision(_on_disk(path)),
            "stage": revision(json.dumps(others, sort_keys=True)) if others else None}


@dataclass(frozen=True)
class SaveOutcome:
    """What a save did: ``saved`` or the reason it refused (``conflict``, ``invalid-over-valid``)."""

    status: str
    revision: str | None = None
    problems: tuple = ()
    difference: str = ""


def _on_disk(path: Path) -> str | None:
    try:
        return read_text(path)
    except FileProblem:
        return None if not path.exists() else ""


def save(data, path: Path, *, opened_revision: str | None, replace_valid: bool = False) -> SaveOutcome:
    """Write *data* to *path* unless the file changed since *opened_revision* or a valid file would become invalid."""
    problems, document = check(data, path)
    text = canonical_text(data, document)
    current = _on_disk(path)
    if revision(current) != opened_revision:
        difference = "".join(difflib.unified_diff((current or "").splitlines(True), text.splitlines(True),
                                                  f"{path.name} (on disk now)", f"{path.name} (yours)"))
        return SaveOutcome("conflict", revision(current), tuple(problem_json(p) for p in problems), difference)
    if problems and current is not None and not replace_valid:
        on_disk_problems, _ = check(json.loads(current), path) if _is_json(current) else ([Problem(str(path), "not JSON")], None)
        if not on_disk_problems:
            return SaveOutcome("invalid-over-valid", revision(current), tuple(problem_json(p) for p in problems))
    write_text(path, text, force=True)
    return SaveOutcome("saved", revision(text), tuple(problem_json(p) for p in problems))


def _is_json(text: str) -> bool:
    try:
        json.loads(text)
    except ValueError:
        return False
    return True
