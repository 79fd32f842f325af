"""``og.Controller.edit`` as Isaac Sim scripts call it, building graphflow graphs.

Porting a script that builds an action graph means changing its import::

    import omni.graph.core as og          ->   from graphflow.build import og

``og.Controller.edit({"graph_path": "/ActionGraph", "evaluator_name": "execution"}, {keys.CREATE_NODES:
[...], keys.SET_VALUES: [...], keys.CONNECT: [...]})`` then returns ``(graph, nodes, prims, lookup)``
like OmniGraph's, where ``graph`` is a ``graphflow.build.Graph``: ``graph.save("cell.json")`` writes
the file ``graphflow run`` reads. Isaac's node type ids (current and ``omni.isaac.*``) and its
``inputs:``/``outputs:`` names are the ones graphflow's node types declare. Edits run in OmniGraph's
order (deletions, variables, nodes, connections, disconnections, values), each checked at once.
"""
from __future__ import annotations

from typing import Any

from graphflow.build.graph import Graph, NodeHandle, Port
from graphflow.errors import BadInput

__all__ = ["Controller", "GraphController", "Type", "BaseDataType", "get_graph_by_path"]


class Keys:
    """The edit keys Isaac scripts use (``og.Controller.Keys``)."""

    CREATE_NODES = "create_nodes"
    CREATE_VARIABLES = "create_variables"
    CONNECT = "connect"
    DISCONNECT = "disconnect"
    DELETE_NODES = "delete_nodes"
    SET_VALUES = "set_values"


SUPPORTED = (Keys.DELETE_NODES, Keys.CREATE_VARIABLES, Keys.CREATE_NODES, Keys.CONNECT, Keys.DISCONNECT,
             Keys.SET_VALUES)   # OmniGraph's order of operations within one edit


class BaseDataType:
    """``og.BaseDataType`` members scripts pass to ``og.Type`` for variables, as graphflow type names."""

    BOOL, INT, UINT, INT64, UINT64 = "bool", "int", "uint", "int64", "uint64"
    FLOAT, DOUBLE, HALF, TOKEN, PATH = "float", "double", "half", "token", "path"


class Type:
    """``og.Type(base, tuple_count=1, array_depth=0)``: a variable's type, spelled as graph files spell it."""

    def __init__(self, base: str, tuple_count: int = 1, array_depth: int = 0):
        self.name = base + (str(tuple_count) if tuple_count > 1 else "") + "[]" * array_depth

    def __str__(self) -> str:
        return self.name


_graphs: dict[str, Graph] = {}


def get_graph_by_path(path: str) -> Graph | None:
    """The graph an earlier ``edit`` made at *path* (``og.get_graph_by_path``)."""
    return _graphs.get(path)


class Controller:
    """``og.Controller``: ``edit`` is what graph-building scripts use."""

    Keys = Keys

    @classmethod
    def edit(cls, graph_id: Any, edit_commands: dict | None = None, **_options) -> tuple:
        """Apply *edit_commands* to the graph *graph_id* names (a dict with ``graph_path``, a path, a Graph)."""
        graph = _graph_of(graph_id)
        commands = dict(edit_commands or {})
        unknown = sorted(set(commands) - set(SUPPORTED))
        if unknown:
            raise BadInput(f"og.Controller.edit: {', '.join(unknown)} not supported here (graphflow builds "
                           f"{', '.join(SUPPORTED)})")
        for name in _as_list(commands.get(Keys.DELETE_NODES)):
            graph.delete(_node_name(name))
        for entry in _as_list(commands.get(Keys.CREATE_VARIABLES)):
            name, type_name, *default = entry
            graph.variable(name, str(type_name), *default)
        created = [graph.node(name, type_id) for name, type_id in _pairs(commands.get(Keys.CREATE_NODES))]
        for src, dst in _pairs(commands.get(Keys.CONNECT)):
            graph.connect(_port(src), _port(dst))
        for src, dst in _pairs(commands.get(Keys.DISCONNECT)):
            graph.disconnect(_port(src), _port(dst))
        values = [(target, value) for target, value, *_type in _pairs(commands.get(Keys.SET_VALUES), width=None)]
        if values:
            graph.set_many({_port(target): value for target, value in values})
        lookup = {node.name: node for node in created}
        return graph, created, [], lookup

    @classmethod
    def attribute(cls, path: Any, node: Any = None) -> str:
        """``og.Controller.attribute("/ActionGraph/node.inputs:x")`` or ``("inputs:x", node)``: the port's full path."""
        if node is not None:
            path = (path, node)
        if not isinstance(path, tuple):
            return str(path)
        attribute, owner = path
        if isinstance(owner, NodeHandle):
            graph_path = next((p for p, graph in _graphs.items() if graph is owner.graph), "")
            return f"{graph_path}/{owner.name}.{attribute}"
        return f"{owner}.{attribute}"   # the node given by its path, "/ActionGraph/node"

    @classmethod
    def set(cls, attribute: Any, value: Any, **_options) -> None:
        """``og.Controller.set(attribute, value)``: author an input of a graph an earlier edit made."""
        graph, port = _graph_and_port(attribute)
        graph.set(port, value)

    @classmethod
    def connect(cls, src: Any, dst: Any, **_options) -> None:
        graph, source = _graph_and_port(src)
        graph.connect(source, _graph_and_port(dst)[1])

    @classmethod
    def disconnect(cls, src: Any, dst: Any, **_options) -> None:
        graph, source = _graph_and_port(src)
        graph.disconnect(source, _graph_and_port(dst)[1])


GraphController = Controller


def _graph_and_port(attribute: Any) -> tuple[Graph, str | Port]:
    """The graph a full attribute path ("/ActionGraph/node.inputs:x") belongs to (the longest graph path first)."""
    text = _port(attribute)
    if isinstance(text, Port):
        matches = [graph for graph in _graphs.values() if graph.document.node(text.node) is not None]
    else:
        matches = [_graphs[path] for path in sorted(_graphs, key=len, reverse=True) if text.startswith(path + "/")]
    if not matches:
        raise BadInput(f"og.Controller: {text}: no graph made by og.Controller.edit holds it "
                       f"(graphs: {', '.join(sorted(_graphs)) or 'none'})")
    return matches[0], text


def _graph_of(graph_id: Any) -> Graph:
    if isinstance(graph_id, Graph):
        return graph_id
    if isinstance(graph_id, dict):
        path = graph_id.get("graph_path")
        evaluator = graph_id.get("evaluator_name", "execution")
        if evaluator != "execution":
            raise BadInput(f"og.Controller.edit: evaluator {evaluator!r}: graphflow runs action graphs "
                           "(evaluator_name 'execution')")
    else:
        path = graph_id
    if not isinstance(path, str) or not path.startswith("/"):
        raise BadInput(f"og.Controller.edit: {graph_id!r} does not name a graph (give {{'graph_path': '/ActionGraph'}})")
    if path not in _graphs:
        _graphs[path] = Graph(description=f"Built by og.Controller.edit at {path}",
                              settings={"evaluator": "execution"})
    return _graphs[path]


def _as_list(entries: Any) -> list:
    if entries is None:
        return []
    return list(entries) if isinstance(entries, list) else [entries]


def _pairs(entries: Any, width: int | None = 2) -> list[tuple]:
    """An edit's list of tuples (one bare tuple is accepted, as OmniGraph accepts it)."""
    if entries is None:
        return []
    items = [entries] if isinstance(entries, tuple) else list(entries)
    for item in items:
        if not isinstance(item, (tuple, list)) or (width is not None and len(item) != width) or len(item) < 2:
            raise BadInput(f"og.Controller.edit: {item!r} is not a ({', '.join(['a', 'b'][:width or 2])}) pair")
    return [tuple(item) for item in items]


def _node_name(node: Any) -> str:
    return node.name if isinstance(node, NodeHandle) else str(node).rsplit("/", 1)[-1]


def _port(port: Any) -> str | Port:
    """A port as scripts write it: ``"node.inputs:x"``, a full path, a Port, or ``("inputs:x", node)``."""
    if isinstance(port, tuple) and len(port) == 2:
        attribute, node = port
        return f"{_node_name(node)}.{attribute}"
    return port if isinstance(port, Port) else str(port)
