"""Kit's ``og.ObjectLookup`` and ``og.DataView`` for graphs an ``og.Controller.edit`` built here.

Scripts look nodes and attributes up after building (``og.Controller.node("/ActionGraph/tick")``,
``og.Controller.attribute("inputs:x", node)``), read values back (``og.Controller.get(attribute)``) and pass
what they got to ``set``/``connect``. Nothing has run when a script builds a graph, so ``get`` answers what
the graph file will hold: an input's authored value, else its declared default; an output has its declared
default, as Kit's outputs do before the first evaluation.
"""
from __future__ import annotations

import json
from typing import Any

from graphflow.build.graph import Graph, NodeHandle
from graphflow.errors import BadInput
from graphflow.usd.node_mapping import GENERIC_PUBLISHERS, MESSAGE_FIELDS

# the graphs ``og.Controller.edit`` made, by graph path (``og._graphs`` is this dict)
BUILT_GRAPHS: dict[str, Graph] = {}


def get_graph_by_path(path: str) -> Graph | None:
    """The graph an earlier ``edit`` made at *path* (``og.get_graph_by_path``)."""
    return BUILT_GRAPHS.get(path)


def get_all_graphs() -> list[Graph]:
    """Every graph an ``edit`` made (``og.get_all_graphs``)."""
    return list(BUILT_GRAPHS.values())


def graph_path(graph: Graph) -> str:
    """The path an edit made *graph* at ("" for a graph built otherwise)."""
    return next((path for path, built in BUILT_GRAPHS.items() if built is graph), "")


def find_graph(graph_id: Any) -> Graph | None:
    """The built graph *graph_id* names (a Graph, its path, ``{"graph_path": path}``, a node of it), or None."""
    if isinstance(graph_id, Graph):
        return graph_id
    if isinstance(graph_id, NodeHandle):
        return graph_id.graph
    path = graph_id.get("graph_path") if isinstance(graph_id, dict) else getattr(graph_id, "pathString", graph_id)
    return BUILT_GRAPHS.get(str(path)) if path is not None else None


class Node(NodeHandle):
    """``og.Node`` as scripts use it: its prim path, type and attributes (a ``NodeHandle`` of the built graph)."""

    def get_prim_path(self) -> str:
        return f"{graph_path(self.graph)}/{self.name}"

    def get_type_name(self) -> str:
        return self.spec.id

    def get_graph(self) -> Graph:
        return self.graph

    def is_valid(self) -> bool:
        """False once the node was deleted from its graph."""
        return self.graph.document.node(self.name) is not None

    def get_attribute_exists(self, name: str) -> bool:
        return self.spec.attribute(name) is not None

    def get_attribute(self, name: str) -> Attribute:
        if not self.get_attribute_exists(name):
            raise BadInput(f"og: node '{self.get_prim_path()}' ({self.spec.id}) has no attribute '{name}'")
        return Attribute(self, name)

    def get_attributes(self) -> list[Attribute]:
        return [Attribute(self, f"inputs:{a.name}") for a in self.spec.inputs] + \
               [Attribute(self, f"outputs:{a.name}") for a in self.spec.outputs]


class Attribute:
    """``og.Attribute``: one port of a built node, named by its full path (``str()`` of it)."""

    def __init__(self, node: Node, name: str):
        self.node, self.name = node, name

    def get_path(self) -> str:
        return f"{self.node.get_prim_path()}.{self.name}"

    def get_name(self) -> str:
        return self.name

    def get_node(self) -> Node:
        return self.node

    def get(self) -> Any:
        return value_of(self)

    def set(self, value: Any) -> None:
        """Author this input, as ``og.Controller.set(attribute, value)`` does."""
        from graphflow.build.og import Controller  # og builds on this module; its setter is needed only here
        Controller.set(self, value)

    def __str__(self) -> str:
        return self.get_path()

    def __repr__(self) -> str:
        return f"og.Attribute({self.get_path()!r})"

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Attribute) and other.node.graph is self.node.graph and str(other) == str(self)

    def __hash__(self) -> int:
        return hash(str(self))


def node(spec: Any, graph: Any = None) -> Node:
    """``og.Controller.node``: a node given as itself, its path, ``(name, graph)``, or a name with *graph*."""
    if isinstance(spec, NodeHandle):
        return Node(spec.graph, spec.name, spec.spec)
    if isinstance(spec, (tuple, list)) and len(spec) == 2:
        spec, graph = spec
    text = str(getattr(spec, "pathString", spec))
    owner = find_graph(graph) if graph is not None else None
    if owner is None and graph is None:
        owner = next((BUILT_GRAPHS[path] for path in sorted(BUILT_GRAPHS, key=len, reverse=True)
                      if text.startswith(path + "/")), None)
    name = text.rsplit("/", 1)[-1]
    entry = owner.document.node(name) if owner is not None else None
    if owner is None or entry is None:
        where = (f"graph {graph_path(owner) or graph}" if owner is not None else f"graph {graph}" if graph is not None
                 else f"graphs built: {', '.join(sorted(BUILT_GRAPHS)) or 'none'}")
        raise BadInput(f"og.Controller.node: no node {text!r} ({where})")
    return Node(owner, name, owner[name].spec)


def attribute(spec: Any, owner: Any = None, graph: Any = None) -> Attribute:
    """``og.Controller.attribute``: ``"/Graph/node.inputs:x"``, ``("inputs:x", node)`` or ``("inputs:x", node)``
    given as two arguments; the port may be one Kit grows dynamically (a generic publisher's message field)."""
    if isinstance(spec, Attribute):
        return spec
    if isinstance(spec, (tuple, list)) and len(spec) in (2, 3):
        spec, owner, *rest = spec
        graph = rest[0] if rest else graph
    text = str(spec)
    if owner is None:
        if "." not in text:
            raise BadInput(f"og.Controller.attribute: {text!r} names no node (give \"/Graph/node.inputs:x\" or "
                           "(\"inputs:x\", node))")
        node_path, text = text.rsplit(".", 1)
        return Attribute(node(node_path, graph), text)
    return Attribute(node(owner, graph), text)


def value_of(port: Attribute) -> Any:
    """The value the graph file gives *port*: see the module docstring."""
    handle, spec, name = port.node.graph.document.node(port.node.name), port.node.spec, port.name
    group, _, short = name.partition(":")
    declared = spec.attribute(name)
    if handle is None:
        raise BadInput(f"og.Controller.get: {port.get_path()}: the node was deleted")
    if group == "inputs" and short in handle.inputs:
        return handle.inputs[short]
    if declared is None and group == "inputs" and spec.id in GENERIC_PUBLISHERS:   # a message field Kit grows
        return json.loads(handle.inputs.get(MESSAGE_FIELDS, "{}")).get(short)
    if declared is None:
        raise BadInput(f"og.Controller.get: {port.get_path()}: {spec.id} has no attribute '{name}'")
    return declared.initial_value()


class ObjectLookup:
    """``og.ObjectLookup``: built graphs, nodes and attributes from the descriptions Kit accepts."""

    @classmethod
    def graph(cls, graph_id: Any) -> Graph | None:
        """The graph an edit made (a path, ``{"graph_path": ...}``, the Graph), or None as Kit answers."""
        return find_graph(graph_id)

    @classmethod
    def node(cls, node_id: Any, graph: Any = None) -> Node:
        return node(node_id, graph)

    @classmethod
    def node_path(cls, node_id: Any, graph: Any = None) -> str:
        return node(node_id, graph).get_prim_path()

    @classmethod
    def attribute(cls, attribute_id: Any, node_id: Any = None, graph: Any = None) -> Attribute:
        return attribute(attribute_id, node_id, graph)

    @classmethod
    def attribute_path(cls, attribute_id: Any, node_id: Any = None, graph: Any = None) -> str:
        return attribute(attribute_id, node_id, graph).get_path()


class DataView:
    """``og.DataView``: ``get`` reads what the built graph gives an attribute (see the module docstring)."""

    def __init__(self, attribute: Any = None):
        self.attribute_id = attribute
        self.get = self._get_own   # type: ignore[method-assign]   # Kit's dual class/object method

    @classmethod
    def get(cls, attribute_id: Any = None, **_options) -> Any:   # type: ignore[misc]
        return value_of(attribute(attribute_id))

    def _get_own(self, attribute_id: Any = None, **_options) -> Any:
        return value_of(attribute(attribute_id if attribute_id is not None else self.attribute_id))
