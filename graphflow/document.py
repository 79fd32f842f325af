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
import tempfile
from functools import lru_cache
from importlib import resources
from pathlib import Path
from typing import Any

from .model import (FORMAT_NAME, FORMAT_VERSION, Connection, GraphDocument, GraphError, NodeDoc, Problem,  # noqa: F401
                    Variable, _frozen)
from .registry import Registry


@lru_cache(maxsize=1)
def json_schema() -> dict:
    """The published JSON Schema of the graph format (also shipped as graphflow/schema/graph.schema.json)."""
    text = resources.files("graphflow").joinpath("schema/graph.schema.json").read_text(encoding="utf-8")
    return json.loads(text)


def _schema_problems(data: Any, source: str) -> list[Problem]:
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
        if node_name:
            problems.append(Problem(source, f"{location}: {error.message}", node=node_name, attribute=None))
        else:
            problems.append(Problem(source, f"{location}: {error.message}"))
    return problems


def parse_document(data: Any, source: str = "<graph>", registry: Registry | None = None) -> GraphDocument:
    """Build and check a document from parsed JSON (schema, then ``graphflow.compiler.compile``); raise GraphError listing every problem."""
    problems = _schema_problems(data, source)
    if problems:
        raise GraphError(problems)
    major = data["formatVersion"][0]
    if major != FORMAT_VERSION[0]:
        raise GraphError([Problem(source, f"formatVersion {data['formatVersion']} is not supported (this runtime reads {FORMAT_VERSION[0]}.x)")])
    document = GraphDocument(
        nodes=tuple(NodeDoc(n["name"], n["type"], n.get("typeVersion"), _frozen(n.get("inputs", {})),
                            n.get("description", "")) for n in data["nodes"]),
        connections=tuple(_parse_connection(c) for c in data.get("connections", [])),
        variables=tuple(Variable(v["name"], v["type"], v.get("default"), v.get("description", ""))
                        for v in data.get("variables", [])),
        settings=_frozen(data.get("settings", {})),
        description=data.get("description", ""),
        ui=_frozen(data.get("ui", {})),
        format_version=tuple(data["formatVersion"]),
        source=source,
        checks=tuple(_frozen(check) for check in data.get("checks", [])),
        scenario=_frozen(data.get("scenario", {})),
    )
    from .compiler import compile   # checking a document is compiling it (the compiler imports this module)

    compile(document, registry)
    return document


def _parse_connection(entry: dict) -> Connection:
    src_node, src_attr = entry["src"].split(".", 1)
    dst_node, dst_attr = entry["dst"].split(".", 1)
    return Connection(src_node, src_attr, dst_node, dst_attr)


def load_document(path: str | os.PathLike, registry: Registry | None = None) -> GraphDocument:
    """Read and validate a graph file."""
    source = str(path)
    try:
        text = Path(path).read_text(encoding="utf-8")
    except FileNotFoundError:
        raise GraphError([Problem(source, "file not found")]) from None
    except (OSError, UnicodeDecodeError) as error:
        raise GraphError([Problem(source, f"cannot read file: {error}")]) from None
    try:
        data = json.loads(text)
    except json.JSONDecodeError as error:
        raise GraphError([Problem(source, f"malformed JSON at line {error.lineno} column {error.colno}: {error.msg}")]) from None
    return parse_document(data, source, registry)


def dumps(document: GraphDocument) -> str:
    """The canonical text of a document: pretty-printed, sorted keys, trailing newline."""
    return json.dumps(document.to_json(), indent=2, sort_keys=True, ensure_ascii=False) + "\n"


def save_document(document: GraphDocument, path: str | os.PathLike) -> None:
    """Write atomically: a temporary file in the same folder, then rename over the target."""
    target = Path(path)
    text = dumps(document)
    handle, temporary = tempfile.mkstemp(prefix=f".{target.name}.", suffix=".tmp", dir=target.parent or ".")
    try:
        with os.fdopen(handle, "w", encoding="utf-8") as stream:
            stream.write(text)
            stream.flush()
            os.fsync(stream.fileno())
        os.replace(temporary, target)
    except BaseException:
        if os.path.exists(temporary):
            os.unlink(temporary)
        raise
