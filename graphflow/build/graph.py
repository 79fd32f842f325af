"""Building graph documents in Python, every call checked at once by the runtime's own compiler.

A ``Graph`` holds the document being built. Each call (``node``, ``set``, ``connect``,
``disconnect``, ``delete``, ``variable``, ``check``) applies its change and checks the whole
document with ``graphflow.document.parse_document`` (the schema, then ``graphflow.compiler``);
a change the runtime would refuse is undone and raised as ``GraphError`` naming the node and port.
So nothing is found late: there is no ``Build()`` after which a mistake surfaces, and what
``save`` writes is exactly what ``graphflow validate`` and ``graphflow run`` read.
"""
from __future__ import annotations

import copy
import os
from dataclasses import dataclass, replace
from pathlib import Path
from typing import TYPE_CHECKING, Any, Iterator, Mapping, NoReturn, TypeVar, overload

from graphflow.document import GraphDocument, dumps, load_document, parse_document, save_document
from graphflow.model import FORMAT_NAME, FORMAT_VERSION, GraphError, Problem
from graphflow.registry import Registry, default_registry
from graphflow.spec import Attribute, NodeSpec

SCHEMA_REFERENCE = "graphflow.schema.json"   # what new graphs' "$schema" names (`graphflow schema -o` writes it)
Handle = TypeVar("Handle", bound="NodeHandle")


@dataclass(frozen=True)
class Port:
    """One port of one node: ``str(port)`` is its ``"node.inputs:x"`` spelling in graph files."""

    node: str
    name: str            # qualified: "inputs:x" / "outputs:y"
    type: str
    description: str = ""

    def __str__(self) -> str:
        return f"{self.node}.{self.name}"


class Ports:
    """A node's inputs or outputs as attributes (``tick.outputs.tick``); ``dir()`` lists them for completion.

    Type checkers see no ``__getattr__``: the typed handles ``graphflow schema --python`` writes declare
    each port, so a misspelled one is flagged before anything runs.
    """

    def __init__(self, node: str, group: str, attributes: tuple[Attribute, ...]):
        self._node, self._group = node, group
        self._attributes = {attribute.name: attribute for attribute in attributes}

    def _lookup(self, name: str) -> Port:
        attributes = self.__dict__.get("_attributes", {})
        if name not in attributes:
            raise AttributeError(f"node '{self._node}' has no {self._group[:-1]} '{name}' "
                                 f"(it has: {', '.join(sorted(attributes)) or 'none'})")
        attribute = attributes[name]
        return Port(self._node, f"{self._group}:{name}", attribute.type, attribute.description)

    if not TYPE_CHECKING:
        def __getattr__(self, name: str) -> Port:
            return self._lookup(name)

    def __getitem__(self, name: str) -> Port:
        return self._lookup(name)

    def __dir__(self) -> list[str]:
        return sorted(self._attributes)

    def __iter__(self) -> Iterator[Port]:
        return (self._lookup(name) for name in self._attributes)


class NodeHandle:
    """A node of a ``Graph``: its ``inputs`` and ``outputs`` as ``Port`` attributes, and ``set(**values)``."""

    TYPE_ID = ""   # typed handle classes (graphflow schema --python) name their node type
    inputs: Any    # Ports; the typed handles declare theirs port by port
    outputs: Any

    def __init__(self, graph: "Graph", name: str, spec: NodeSpec):
        self.graph, self.name, self.spec = graph, name, spec
        self.inputs = Ports(name, "inputs", spec.inputs)
        self.outputs = Ports(name, "outputs", spec.outputs)

    @property
    def type(self) -> str:
        return self.spec.id

    def set(self, **values: Any) -> "NodeHandle":
        """Author several input values at once (all checked together)."""
        self.graph.set_many({f"{self.name}.inputs:{name}": value for name, value in values.items()})
        return self

    def __repr__(self) -> str:
        return f"NodeHandle({self.name!r}, {self.spec.id!r})"


class Graph:
    """A graph document under construction; see the module docstring."""

    def __init__(self, *, description: str = "", settings: Mapping[str, Any] | None = None,
                 registry: Registry | None = None, source: str = "<graph>", schema: str | None = SCHEMA_REFERENCE):
        self.registry = registry or default_registry()
        self.source = source
        self._data: dict[str, Any] = {"format": FORMAT_NAME, "formatVersion": list(FORMAT_VERSION), "nodes": []}
        if schema:
            self._data["$schema"] = schema
        if description:
            self._data["description"] = description
        if settings:
            self._data["settings"] = dict(settings)
        self._document = self._checked(self._data)

    # ------------------------------------------------------------------ loading and saving

    @classmethod
    def load(cls, path: str | os.PathLike, registry: Registry | None = None) -> "Graph":
        """Continue building a graph file (its text is kept as written: load -> save is byte-identical)."""
        document = load_document(path, registry)
        graph = cls.__new__(cls)
        graph.registry = registry or default_registry()
        graph.source = str(path)
        graph._data = document.to_json()
        graph._document = document
        return graph

    @property
    def document(self) -> GraphDocument:
        """The checked document as it stands (immutable: later calls make a new one)."""
        return self._document

    def dumps(self) -> str:
        """The canonical JSON text ``save`` writes."""
        return dumps(self._document)

    def save(self, path: str | os.PathLike, *, force: bool = True) -> Path:
        """Write the canonical JSON atomically (a relative stage path is rebased onto *path*'s folder)."""
        save_document(self._document, path, force=force)
        return Path(path)

    # ------------------------------------------------------------------ nodes

    @overload
    def node(self, name: str, node_type: type[Handle], /, **inputs: Any) -> Handle: ...

    @overload
    def node(self, name: str, node_type: str, /, **inputs: Any) -> NodeHandle: ...

    def node(self, name, node_type, /, **inputs):
        """Create node *name* of a type id (Isaac's legacy ids load too) or a typed handle class
        (``graphflow schema --python``), with input values; returns its handle."""
        handle_class = node_type if isinstance(node_type, type) else NodeHandle
        type_id = node_type.TYPE_ID if isinstance(node_type, type) else node_type
        entry: dict[str, Any] = {"name": name, "type": type_id}
        if inputs:
            entry["inputs"] = {key: plain(value) for key, value in inputs.items()}
        if self._find(name) is not None:
            self._refuse(f"a node named '{name}' already exists", node=name)
        self._change(lambda data: data["nodes"].append(entry))
        return handle_class(self, name, self.registry.get(type_id).spec)

    def __getitem__(self, name: str) -> NodeHandle:
        """The handle of an existing node."""
        entry = self._find(name)
        if entry is None:
            self._refuse("no such node", node=name)
        return NodeHandle(self, name, self._spec_of(entry))

    def nodes(self) -> list[NodeHandle]:
        return [self[entry["name"]] for entry in self._data["nodes"]]

    def delete(self, *nodes: str | NodeHandle) -> None:
        """Delete nodes and every connection to or from them (as OmniGraph does)."""
        names = {node.name if isinstance(node, NodeHandle) else str(node) for node in nodes}
        for name in sorted(names):
            if self._find(name) is None:
                self._refuse("cannot delete: no such node", node=name)

        def remove(data):
            data["nodes"] = [n for n in data["nodes"] if n["name"] not in names]
            kept = [c for c in data.get("connections", []) if c["src"].split(".", 1)[0] not in names
                    and c["dst"].split(".", 1)[0] not in names]
            _set_list(data, "connections", kept)
        self._change(remove)

    # ------------------------------------------------------------------ values

    def set(self, target: str | Port, value: Any) -> None:
        """Author the value of an input: ``set("move.inputs:speed", 0.5)`` or ``set(move.inputs.speed, 0.5)``."""
        self.set_many({target: value})

    def set_many(self, values: Mapping[str | Port, Any]) -> None:
        """Author several input values in one checked change."""
        resolved = [(*self._endpoint(target, "inputs"), plain(value)) for target, value in values.items()]

        def author(data):
            for node, attribute, value in resolved:
                entry = next(n for n in data["nodes"] if n["name"] == node)
                entry.setdefault("inputs", {})[attribute.split(":", 1)[1]] = value
        self._change(author)

    def unset(self, target: str | Port) -> None:
        """Remove an authored value: the input goes back to its default."""
        node, attribute = self._endpoint(target, "inputs")

        def remove(data):
            entry = next(n for n in data["nodes"] if n["name"] == node)
            inputs = entry.get("inputs", {})
            inputs.pop(attribute.split(":", 1)[1], None)
            if not inputs:
                entry.pop("inputs", None)
        self._change(remove)

    # ------------------------------------------------------------------ connections

    def connect(self, src: str | Port, dst: str | Port) -> None:
        """Connect an output to an input: ``"tick.outputs:tick"`` strings or ``Port`` handles."""
        (src_node, src_attr), (dst_node, dst_attr) = self._endpoint(src, "outputs"), self._endpoint(dst, "inputs")
        entry = {"src": f"{src_node}.{src_attr}", "dst": f"{dst_node}.{dst_attr}"}
        if entry in self._data.get("connections", []):
            self._refuse(f"{entry['src']} is already connected to it", node=dst_node, attribute=dst_attr,
                         kind="connection")
        self._change(lambda data: data.setdefault("connections", []).append(entry))

    def disconnect(self, src: str | Port, dst: str | Port) -> None:
        (src_node, src_attr), (dst_node, dst_attr) = self._endpoint(src, "outputs"), self._endpoint(dst, "inputs")
        entry = {"src": f"{src_node}.{src_attr}", "dst": f"{dst_node}.{dst_attr}"}
        if entry not in self._data.get("connections", []):
            self._refuse(f"cannot disconnect: {entry['src']} is not connected to it", node=dst_node,
                         attribute=dst_attr, kind="connection")
        self._change(lambda data: _set_list(data, "connections", [c for c in data["connections"] if c != entry]))

    # ------------------------------------------------------------------ variables, checks, settings

    def variable(self, name: str, type_name: str, default: Any = None, description: str = "") -> None:
        """Create a graph variable (read and written by ReadVariable / WriteVariable nodes)."""
        entry: dict[str, Any] = {"name": name, "type": type_name}
        if default is not None:
            entry["default"] = plain(default)
        if description:
            entry["description"] = description
        if any(v["name"] == name for v in self._data.get("variables", [])):
            self._refuse("a variable of that name already exists", attribute=name, kind="variable")
        self._change(lambda data: data.setdefault("variables", []).append(entry))

    def check(self, kind: str, **fields: Any) -> None:
        """Add a check a run must pass (docs/checks.md): ``check("position", prim=..., position=..., tolerance=...)``."""
        entry = {"check": kind, **{key: plain(value) for key, value in fields.items()}}
        self._change(lambda data: data.setdefault("checks", []).append(entry))

    def setting(self, name: str, value: Any) -> None:
        """Set one of ``settings`` (stage, timeStep, duration, ...)."""
        self._change(lambda data: data.setdefault("settings", {}).__setitem__(name, plain(value)))

    # ------------------------------------------------------------------ checking

    def _change(self, edit) -> None:
        """Apply *edit* to a copy of the data; keep it only when the whole document still checks.

        The schema is checked on the entries the edit changed (the others passed it before), the
        compiler on the whole document. The data is never changed in place, so the document may share it.
        """
        data = copy.deepcopy(self._data)
        edit(data)
        self._document = self._checked(data, _changed_entries_schema(self._data))
        self._data = data

    def _checked(self, data: dict, schema_problems=None) -> GraphDocument:
        return parse_document(data, self.source, self.registry, schema_problems=schema_problems)

    def _spec_of(self, entry: dict) -> NodeSpec:
        node_type = self.registry.get(entry["type"])
        assert node_type is not None   # every node in the document compiled, so its type is registered
        return node_type.spec

    def _find(self, name: str) -> dict | None:
        return next((entry for entry in self._data["nodes"] if entry["name"] == name), None)

    def _endpoint(self, port: str | Port, group: str) -> tuple[str, str]:
        """(node, "group:name") of a port given as a handle or a ``"node.group:name"`` string, checked."""
        text = str(port)
        marker = text.find(f".{group}:")
        if marker <= 0:
            self._refuse(f"{text!r} is not an {group[:-1]} (write \"node.{group}:name\")")
        node, attribute = text[:marker].rsplit("/", 1)[-1], text[marker + 1:]   # "/ActionGraph/tick..." too
        entry = self._find(node)
        if entry is None:
            self._refuse(f"no such node (in {text!r})", node=node, attribute=attribute, kind="connection")
        spec = self._spec_of(entry)
        if spec.attribute(attribute) is None and attribute.count(":") > 1:   # Kit's primvars:st is primvars_st here
            attribute = group + ":" + attribute.split(":", 1)[1].replace(":", "_")
        if spec.attribute(attribute) is None:
            names = ", ".join(a.name for a in (spec.inputs if group == "inputs" else spec.outputs))
            self._refuse(f"{spec.id} has no {group[:-1]} '{attribute.split(':', 1)[1]}' (it has: {names})",
                         node=node, attribute=attribute, kind=group[:-1])
        return node, attribute

    def _refuse(self, message: str, **where) -> NoReturn:
        raise GraphError([Problem(self.source, message, **where)])


_SECTIONS = ("nodes", "connections", "variables", "checks")


def _changed_entries_schema(before: dict):
    """A schema check of only the section entries that differ from *before*, its problems at their real index."""
    from graphflow.document import document_schema_problems

    def check(data: dict, source: str) -> list[Problem]:
        reduced = {key: value for key, value in data.items() if key not in _SECTIONS}
        positions = {}
        for section in _SECTIONS:
            if section in data:
                old, new = before.get(section, []), data[section]
                positions[section] = [i for i, entry in enumerate(new) if i >= len(old) or entry != old[i]]
                reduced[section] = [new[i] for i in positions[section]]
        reduced.setdefault("nodes", [])
        return [_at_real_index(problem, positions) for problem in document_schema_problems(reduced, source)]
    return check


def _at_real_index(problem: Problem, positions: dict) -> Problem:
    path = problem.path
    if len(path) < 2 or path[0] not in positions:
        return problem
    real = (path[0], positions[path[0]][path[1]], *path[2:])
    shown = "/".join(str(part) for part in path)
    return replace(problem, message="/".join(str(part) for part in real) + problem.message[len(shown):], path=real)


def _set_list(data: dict, key: str, items: list) -> None:
    """Keep optional sections absent when empty, as the canonical JSON writes them."""
    if items:
        data[key] = items
    else:
        data.pop(key, None)


def plain(value: Any) -> Any:
    """A value as JSON holds it: tuples and arrays become lists, USD paths their strings."""
    if hasattr(value, "tolist"):            # numpy arrays and scalars
        value = value.tolist()
    if isinstance(value, (list, tuple)):
        return [plain(item) for item in value]
    if isinstance(value, dict):
        return {str(key): plain(item) for key, item in value.items()}
    if value is None or isinstance(value, (bool, int, float, str)):
        return value
    if hasattr(value, "pathString"):        # pxr / usdrt Sdf.Path
        return str(value.pathString)
    raise GraphError([Problem("<graph>", f"{value!r} ({type(value).__name__}) is not a value a graph file can hold")])
