"""Graph documents: the JSON file format, its schema, and atomic saving.

A ``GraphDocument`` is immutable and holds authored values exactly as written,
so load -> save -> load is byte-identical. Loading reports every problem of a
file at once, each as one line naming the file, node and attribute: the schema
here, then everything about node types, values and connections by compiling
the document (``graphflow.compiler``).
"""
from __future__ import annotations

import json
import os
from dataclasses import replace
from functools import lru_cache
from importlib import resources
from pathlib import Path
from typing import Any

from graphflow.files import FileProblem, read_json, write_text
from graphflow.model import (  # noqa: F401
    FORMAT_NAME,
    FORMAT_VERSION,
    Connection,
    GraphDocument,
    GraphError,
    NodeDoc,
    Problem,
    Variable,
    frozen_mapping,
)
from graphflow.registry import Registry


@lru_cache(maxsize=1)
def json_schema() -> dict:
    """The published JSON Schema of the graph format (also shipped as graphflow/schema/graph.schema.json)."""
    text = resources.files("graphflow").joinpath("schema/graph.schema.json").read_text(encoding="utf-8")
    return json.loads(text)


def document_schema_problems(data: Any, source: str) -> list[Problem]:
    import jsonschema

    validator = jsonschema.Draft202012Validator(json_schema())
    problems = []
    for error in sorted(validator.iter_errors(data), key=lambda e: [str(p) for p in e.absolute_path]):
        path = error.absolute_path
        node_name = None
        if len(path) >= 2 and path[0] == "nodes" and isinstance(data, dict):
            try:
                node_name = data["nodes"][path[1]].get("name")
            except (IndexError, AttributeError, KeyError, TypeError):
                node_name = None
        location = "/".join(str(p) for p in path) or "document"
        message = error.message
        if error.validator == "pattern" and path and path[-1] == "name":
            message = f"{error.instance!r} is not a name (letters, digits, '_' and '-', not starting with a digit or '-')"
        if not isinstance(node_name, str):
            node_name = None
        problems.append(Problem(source, f"{location}: {message}", node=node_name, path=tuple(path)))
    return problems


def parse_document(data: Any, source: str = "<graph>", registry: Registry | None = None, *,
                   schema_problems=None) -> GraphDocument:
    """Build and check a document from parsed JSON (schema, then ``graphflow.compiler.compile``); raise GraphError listing every problem.

    *schema_problems* replaces the whole-file schema check (``graphflow.build`` checks only the entries a call changed).
    """
    problems = (schema_problems or document_schema_problems)(data, source)
    if problems:
        raise GraphError(problems + _problems_of_valid_parts(data, source, registry, problems))
    major = data["formatVersion"][0]
    if major != FORMAT_VERSION[0]:
        raise GraphError([Problem(source, f"formatVersion {data['formatVersion']} is not supported (this runtime reads {FORMAT_VERSION[0]}.x)")])
    document = GraphDocument(
        nodes=tuple(NodeDoc(n["name"], n["type"], n.get("typeVersion"), frozen_mapping(n.get("inputs", {})),
                            n.get("description", "")) for n in data["nodes"]),
        connections=tuple(_parse_connection(c) for c in data.get("connections", [])),
        variables=tuple(Variable(v["name"], v["type"], v.get("default"), v.get("description", ""))
                        for v in data.get("variables", [])),
        settings=frozen_mapping(data.get("settings", {})),
        description=data.get("description", ""),
        ui=frozen_mapping(data.get("ui", {})),
        format_version=tuple(data["formatVersion"]),
        source=source,
        checks=tuple(frozen_mapping(check) for check in data.get("checks", [])),
        scenario=frozen_mapping(data.get("scenario", {})),
        schema=data.get("$schema", ""),
    )
    from graphflow.compiler import compile  # checking a document is compiling it

    compile(document, registry)
    return document


def _problems_of_valid_parts(data: Any, source: str, registry: Registry | None, schema_problems) -> list[Problem]:
    """Semantic problems of the entries the schema accepted, so one pass lists both kinds."""
    if not isinstance(data, dict) or not isinstance(data.get("nodes"), list):
        return []
    from graphflow.compiler import problems

    broken = {tuple(p.path[:2]) for p in schema_problems if len(p.path) >= 2}
    broken_sections = {p.path[0] for p in schema_problems if len(p.path) == 1}

    def kept(section: str) -> list:
        entries = data.get(section, [])
        if section in broken_sections or not isinstance(entries, list):
            return []
        return [entry for index, entry in enumerate(entries) if (section, index) not in broken]

    skipped = {entry.get("name") for index, entry in enumerate(data["nodes"])
               if ("nodes", index) in broken and isinstance(entry, dict) and isinstance(entry.get("name"), str)}
    settings = data.get("settings", {})
    document = GraphDocument(
        nodes=tuple(NodeDoc(n["name"], n["type"], n.get("typeVersion"), frozen_mapping(n.get("inputs", {})))
                    for n in kept("nodes")),
        connections=tuple(_parse_connection(c) for c in kept("connections")),
        variables=tuple(Variable(v["name"], v["type"], v.get("default")) for v in kept("variables")),
        settings=frozen_mapping(settings if isinstance(settings, dict) and "settings" not in broken_sections
                         and not any(p.path[:1] == ("settings",) for p in schema_problems) else {}),
        source=source)
    return [problem for problem in problems(document, registry) if problem.node not in skipped]


def _parse_connection(entry: dict) -> Connection:
    src_node, src_attr = entry["src"].split(".", 1)
    dst_node, dst_attr = entry["dst"].split(".", 1)
    return Connection(src_node, src_attr, dst_node, dst_attr)


def load_document(path: str | os.PathLike, registry: Registry | None = None) -> GraphDocument:
    """Read (strict JSON: see graphflow.files) and check a graph file; older typeVersions are migrated (graphflow.migration)."""
    try:
        data = read_json(path)
    except FileProblem as error:
        raise GraphError([Problem(str(path), error.reason)]) from None
    from graphflow.migration import migrate_on_load

    return migrate_on_load(parse_document(data, str(path), registry), registry)


def dumps(document: GraphDocument) -> str:
    """The canonical text of a document: pretty-printed, sorted keys, trailing newline."""
    return json.dumps(document.to_json(), indent=2, sort_keys=True, ensure_ascii=False) + "\n"


def save_document(document: GraphDocument, path: str | os.PathLike, *, force: bool = True) -> None:
    """Write atomically (graphflow.files.write_text): never half-written, over an existing file only with *force*.

    A relative ``settings.stage`` is rebased onto the new file's folder, so the saved graph still finds its stage.
    """
    write_text(path, dumps(rebased(document, path)), force=force)


def rebased(document: GraphDocument, path: str | os.PathLike) -> GraphDocument:
    """*document* as it must read when saved at *path*: its relative stage path made relative to that folder."""
    stage = document.settings.get("stage")
    if not isinstance(stage, str) or stage.startswith(("asset:", "@")) or Path(stage).is_absolute():
        return document
    if not (document.base_dir / stage).exists():
        return document   # names no file here: an asset root's (graphflow/ur10.usda, found from any folder) or none
    folder = Path(path).resolve().parent
    if folder == document.base_dir:
        return document
    moved = Path(os.path.relpath(document.base_dir / stage, folder)).as_posix()
    return replace(document, settings=frozen_mapping({**document.settings, "stage": moved}), source=str(path))
