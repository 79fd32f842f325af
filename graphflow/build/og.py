"""``og.Controller.edit`` as Isaac Sim scripts call it, building graphflow graphs.

Porting a script that builds an action graph means changing its import::

    import omni.graph.core as og          ->   from graphflow.build import og

``og.Controller.edit({"graph_path": "/ActionGraph", "evaluator_name": "execution"}, {keys.CREATE_NODES:
[...], keys.SET_VALUES: [...], keys.CONNECT: [...]})`` then returns ``(graph, nodes, prims, lookup)``
like OmniGraph's, where ``graph`` is a ``graphflow.build.Graph``: ``graph.save("cell.json")`` writes
the file ``graphflow run`` reads. Isaac's node type ids (current and ``omni.isaac.*``) and its
``inputs:``/``outputs:`` names are the ones graphflow's node types declare. Edits run in OmniGraph's
order (deletions, variables, nodes, attributes, connections, disconnections, values), each checked at
once. What the importer of ``.usda`` graphs degrades, this degrades the same way, with one warning line
(``OgCompatWarning``) each: renderer and GUI node types are dropped with their connections and values, an
evaluator other than ``execution`` or an on-demand pipeline stage builds an action graph evaluated every tick,
a connection from a constant's ``inputs:value`` reads its output, as Kit lets it, a generic subscriber's
per-field output is read from its message (``graphflow.ROS2MessageField``) and a generic publisher's per-field
values gather into ``messageFields``, Isaac 4.x's Surface Gripper maps as on import (``og_legacy``), and inputs
Isaac removed since 4.x (``REMOVED_INPUTS``) are dropped.
"""
from __future__ import annotations

import json
import warnings
import weakref
from typing import Any

from pxr import Sdf

from graphflow.build import og_legacy, og_lookup
from graphflow.build.graph import Graph, NodeHandle, Port
from graphflow.build.og_lookup import BUILT_GRAPHS, DataView, ObjectLookup, get_all_graphs, get_graph_by_path
from graphflow.build.og_names import (
    REMOVED_INPUTS,
    SUPPORTED,
    AttributeRole,
    BaseDataType,
    GraphPipelineStage,
    Keys,
    Type,
    variable_type,
)
from graphflow.errors import BadInput
from graphflow.spec import NodeSpec
from graphflow.usd.node_mapping import (
    GENERIC_PUBLISHERS,
    GENERIC_SUBSCRIBERS,
    MESSAGE_FIELDS,
    RENDERING_NODES,
    gather_message_fields,
)

MESSAGE_FIELD = "graphflow.ROS2MessageField"

__all__ = ["Controller", "GraphController", "ObjectLookup", "DataView", "Type", "BaseDataType", "AttributeRole",
           "GraphPipelineStage", "OgCompatWarning", "get_graph_by_path", "get_all_graphs"]


class OgCompatWarning(UserWarning):
    """One line about what an edit carried over differently from Kit (a dropped node, the evaluator)."""


# ``graphflow import --skip-unknown`` for scripts: set ``og.skip_unknown = True`` after the import and node types
# graphflow lacks are left out with one line each (their connections and values too) instead of refused
skip_unknown = False

_graphs = BUILT_GRAPHS
_dropped: "weakref.WeakKeyDictionary[Graph, set[str]]" = weakref.WeakKeyDictionary()   # renderer nodes left out
_legacy: "weakref.WeakKeyDictionary[Graph, set[str]]" = weakref.WeakKeyDictionary()    # Isaac 4.x grippers (v1)


class Controller(ObjectLookup, DataView):
    """``og.Controller``: ``edit`` is what graph-building scripts use; lookups (``node``, ``attribute``, ``graph``)
    and ``get`` come from ``og_lookup``. An instance (``og.Controller(graph_id)``) edits and evaluates its graph
    when none is given, gets and sets its ``attribute``, as Kit's object methods do."""

    Keys = Keys

    def __init__(self, *args: Any, **kwargs: Any):
        first = args[0] if args else None
        own_attribute = first if isinstance(first, og_lookup.Attribute) else None
        DataView.__init__(self, kwargs.get("attribute", own_attribute))
        self.graph_id = kwargs.get("graph_id", None if own_attribute is not None else first)
        self.edit = self._edit_own              # type: ignore[method-assign]
        self.evaluate_sync = self._evaluate_own  # type: ignore[method-assign]
        self.evaluate = self._evaluate_async_own  # type: ignore[method-assign]
        self.set = self._set_own                # type: ignore[method-assign]

    def _edit_own(self, *args: Any, **kwargs: Any) -> tuple:
        """``controller.edit(commands)`` on its graph, or ``controller.edit(graph_id, commands)``; it keeps the graph."""
        commands_only = bool(args) and isinstance(args[0], dict) and "graph_path" not in args[0]
        graph_id = self.graph_id if commands_only or not args else args[0]
        rest = args if commands_only else args[1:]
        graph_id = kwargs.pop("graph_id", graph_id)
        if graph_id is None:
            raise BadInput("og.Controller().edit: no graph given (og.Controller(\"/ActionGraph\") or edit(graph_id, ...))")
        result = Controller.edit(graph_id, *rest, **kwargs)
        self.graph_id = result[0]
        return result

    def _evaluate_own(self, graph_id: Any = None, **_options: Any) -> None:
        Controller.evaluate_sync(graph_id if graph_id is not None else self.graph_id)

    async def _evaluate_async_own(self, graph_id: Any = None, **_options: Any) -> None:
        self._evaluate_own(graph_id)

    def _set_own(self, *args: Any, **options: Any) -> None:
        """``controller.set(value)`` on its attribute, or ``controller.set(attribute, value)``."""
        if len(args) == 1 and self.attribute_id is not None:
            args = (self.attribute_id, args[0])
        Controller.set(*args, **options)

    @classmethod
    def evaluate_sync(cls, graph_id: Any = None, **_options: Any) -> None:   # type: ignore[misc]
        """Not an evaluation: the script builds the graph; ``graphflow run`` evaluates it every tick (one line)."""
        ids = graph_id if isinstance(graph_id, list) else [graph_id] if graph_id is not None else None
        paths = sorted(BUILT_GRAPHS) if ids is None else [og_lookup.graph_path(cls._existing(i)) for i in ids]
        _warn(f"evaluate({', '.join(paths) or 'no graphs'}): not evaluated here: the script builds the graph; "
              "`graphflow run FILE` evaluates it every tick")

    @classmethod
    async def evaluate(cls, graph_id: Any = None, **_options: Any) -> None:
        cls.evaluate_sync(graph_id)

    @classmethod
    def _existing(cls, graph_id: Any) -> Graph:
        graph = og_lookup.find_graph(graph_id)
        if graph is None:
            raise BadInput(f"og.Controller: the graph {graph_id!r} does not exist (graphs built: "
                           f"{', '.join(sorted(BUILT_GRAPHS)) or 'none'})")
        return graph

    @classmethod
    def create_graph(cls, graph_id: Any, **_options: Any) -> Graph:
        return _graph_of(graph_id)

    @classmethod
    def create_node(cls, node_id: Any, node_type_id: str, **_options: Any) -> NodeHandle | None:
        """A node at ``"/Graph/name"`` or ``("name", graph)`` in a graph already made; None when dropped (one line)."""
        if not isinstance(node_id, tuple) and "/" not in str(node_id):
            raise BadInput(f"og.Controller.create_node: {node_id!r} names no graph (give \"/Graph/name\" or (name, graph))")
        name, graph_part = node_id if isinstance(node_id, tuple) else reversed(str(node_id).rsplit("/", 1))
        made = _create(cls._existing(graph_part), name, node_type_id)
        return og_lookup.node(made) if made is not None else None

    @classmethod
    def delete_node(cls, node_id: Any, **_options: Any) -> None:
        found = og_lookup.node(node_id)
        found.graph.delete(found.name)

    @classmethod
    def create_variable(cls, graph_id: Any, name: str, var_type: Any, **_options: Any) -> None:
        cls._existing(graph_id).variable(name, str(var_type))

    @classmethod
    def attribute(cls, attribute_id: Any, node_id: Any = None, graph: Any = None) -> Any:
        """``og.Controller.attribute``; a port of a node the edit dropped stays its path (its uses are dropped too)."""
        try:
            return og_lookup.attribute(attribute_id, node_id, graph)
        except BadInput:
            port = _port((attribute_id, node_id) if node_id is not None else attribute_id)
            matches = [g for path, g in BUILT_GRAPHS.items() if str(port).startswith(path + "/")]
            if matches and _node_of(matches[0], port) in _dropped.get(matches[0], set()):
                return port
            raise

    @classmethod
    def edit(cls, graph_id: Any, edit_commands: dict | None = None, **_options) -> tuple:   # type: ignore[misc]
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
            graph.variable(name, variable_type(type_name), *default)
        made = [_create(graph, name, type_id) for name, type_id in _pairs(commands.get(Keys.CREATE_NODES))]
        created = [og_lookup.node(node) for node in made if node is not None]
        for target, *_type in _pairs(commands.get(Keys.CREATE_ATTRIBUTES), width=None):
            _declared(graph, _port(target))
        for src, dst in _wired(graph, _kept(graph, _pairs(commands.get(Keys.CONNECT)))):
            graph.connect(_mapped(graph, _source(graph, src)), _mapped(graph, _port(dst)))
        for src, dst in _kept(graph, _pairs(commands.get(Keys.DISCONNECT))):
            graph.disconnect(_mapped(graph, _source(graph, src)), _mapped(graph, _port(dst)))
        for attribute in _as_list(commands.get(Keys.DISCONNECT_ALL)):
            _disconnect_all(graph, _port(attribute))
        values = _current(graph, _kept(graph, [(target, value) for target, value, *_type
                                               in _pairs(commands.get(Keys.SET_VALUES), width=None)], ports=1))
        if values:
            graph.set_many(_legacy_values(graph, _absolute(graph, {_port(target): value for target, value in values})))
        lookup = {node.name: node for node in created}
        return graph, created, [], lookup

    @classmethod
    def set(cls, attribute: Any, value: Any, **_options) -> None:   # type: ignore[misc]
        """``og.Controller.set(attribute, value)``: author an input of a graph an earlier edit made."""
        graph, port = _graph_and_port(attribute)
        if _current(graph, _kept(graph, [(port, value)], ports=1)):
            graph.set_many(_legacy_values(graph, _absolute(graph, {port: value})))

    @classmethod
    def connect(cls, src: Any, dst: Any, **_options) -> None:
        graph, source = _graph_and_port(src)
        if _wired(graph, _kept(graph, [(source, _graph_and_port(dst)[1])])):
            graph.connect(_mapped(graph, _source(graph, source)), _mapped(graph, _graph_and_port(dst)[1]))

    @classmethod
    def disconnect_all(cls, attribute: Any, **_options) -> None:
        graph, port = _graph_and_port(attribute)
        _disconnect_all(graph, port)

    @classmethod
    def disconnect(cls, src: Any, dst: Any, **_options) -> None:
        graph, source = _graph_and_port(src)
        if _kept(graph, [(source, _graph_and_port(dst)[1])]):
            graph.disconnect(_mapped(graph, _source(graph, source)), _mapped(graph, _graph_and_port(dst)[1]))


GraphController = Controller


def _graph_and_port(attribute: Any) -> tuple[Graph, str | Port]:
    """The graph a full attribute path ("/ActionGraph/node.inputs:x") belongs to (the longest graph path first)."""
    text = _port(attribute)
    if isinstance(attribute, tuple) and len(attribute) == 2 and isinstance(attribute[1], NodeHandle):
        return attribute[1].graph, text   # ("inputs:x", node): the node's own graph
    if isinstance(text, Port):
        matches = [graph for graph in _graphs.values() if graph.document.node(text.node) is not None]
    else:
        matches = [_graphs[path] for path in sorted(_graphs, key=len, reverse=True) if text.startswith(path + "/")]
    if not matches:
        raise BadInput(f"og.Controller: {text}: no graph made by og.Controller.edit holds it "
                       f"(graphs: {', '.join(sorted(_graphs)) or 'none'})")
    return matches[0], text


def _disconnect_all(graph: Graph, port: str | Port) -> None:
    """Every connection to or from *port* broken (``DISCONNECT_ALL``)."""
    node = _node_of(graph, port)
    name = f"{node}.{str(port).rsplit('.', 1)[-1]}"
    for connection in graph.document.connections:
        if name in (connection.src, connection.dst):
            graph.disconnect(connection.src, connection.dst)


def _graph_of(graph_id: Any) -> Graph:
    if isinstance(graph_id, Graph):
        return graph_id
    path = graph_id.get("graph_path") if isinstance(graph_id, dict) else graph_id
    if not isinstance(path, str) or not path.startswith("/"):
        raise BadInput(f"og.Controller.edit: {graph_id!r} does not name a graph (give {{'graph_path': '/ActionGraph'}})")
    if isinstance(graph_id, dict) and path not in _graphs:
        evaluator = graph_id.get("evaluator_name", "execution")
        if evaluator != "execution":
            _warn(f"{path}: evaluator {evaluator!r} built as an action graph (execution)")
        if graph_id.get("pipeline_stage") == GraphPipelineStage.GRAPH_PIPELINE_STAGE_ONDEMAND:
            _warn(f"{path}: pipeline stage on-demand built as a graph evaluated every tick (the script's own "
                  "evaluate calls are not carried over)")
    if path not in _graphs:
        _graphs[path] = Graph(description=f"Built by og.Controller.edit at {path}",
                              settings={"evaluator": "execution"})
    return _graphs[path]


def _warn(line: str) -> None:
    warnings.warn(OgCompatWarning(f"og.Controller.edit: {line}"), stacklevel=4)


def _create(graph: Graph, name: str, type_id: Any) -> NodeHandle | None:
    """The node, or None for a renderer/GUI type (or, with ``skip_unknown``, a type graphflow lacks), dropped with
    one line as the importer drops it."""
    if not isinstance(type_id, str):   # a dict of edits makes a compound node in Kit
        raise BadInput(f"og.Controller.edit: node '{name}': {type(type_id).__name__} as its type: compound nodes "
                       "(a subgraph of edits) are not built here; give a node type id")
    reason = RENDERING_NODES.get(type_id)
    if reason is None and skip_unknown and graph.registry.get(type_id) is None and type_id != og_legacy.V1_ID:
        hint = graph.registry.suggest(type_id)
        reason = "unknown node type" + (f" (did you mean {hint!r}?)" if hint else "") + "; skipped (og.skip_unknown)"
    if reason is not None:
        _dropped.setdefault(graph, set()).add(name)
        _warn(f"node '{name}' ({type_id}): dropped with its connections and values: {reason}")
        return None
    if type_id == og_legacy.V1_ID:
        _legacy.setdefault(graph, set()).add(name)
        return og_legacy.create(graph, name, _warn)
    return graph.node(name, type_id)


def _mapped(graph: Graph, port: str | Port) -> str | Port:
    """*port* as the mapped graph has it: an Isaac 4.x gripper's v1 pins moved to the nodes standing for it."""
    node = _node_of(graph, port)
    if isinstance(port, Port) or node not in _legacy.get(graph, set()):
        return port
    return og_legacy.endpoint(graph, node, str(port).rsplit(".", 1)[1], _warn)


def _field_input(graph: Graph, port: str | Port) -> tuple[str, str] | None:
    """(node, field) when *port* is a per-field input Kit gives a generic publisher (``inputs:header:stamp:sec``)."""
    node, text = _node_of(graph, port), str(port)
    spec = _spec_of(graph, node)
    if spec is None or spec.id not in GENERIC_PUBLISHERS or ".inputs:" not in text:
        return None
    field = text.rsplit(".inputs:", 1)[1]
    return None if spec.attribute(f"inputs:{field}") is not None else (node, field)


def _wired(graph: Graph, pairs: list) -> list:
    """*pairs* without connections into a generic publisher's message fields, dropped with a line as on import."""
    kept = []
    for src, dst in pairs:
        field = _field_input(graph, _port(dst))
        if field is None:
            kept.append((src, dst))
        else:
            _warn(f"node '{field[0]}' input 'inputs:{field[1]}': connection from {_port(src)} dropped: graphflow's "
                  f"publisher takes its message fields as values ('inputs:{MESSAGE_FIELDS}'), not connections")
    return kept


def _absolute(graph: Graph, values: dict) -> dict:
    """*values* with relative target paths ("../..") made absolute against the node's prim, as USD resolves a
    relationship's targets and Kit the node's (the node's prim is ``<graph path>/<node name>``)."""
    graph_path = next((path for path, made in _graphs.items() if made is graph), "")
    resolved = {}
    for target, value in values.items():
        node = _node_of(graph, target)
        spec = _spec_of(graph, node)
        attribute = spec.attribute("inputs:" + str(target).rsplit(".inputs:", 1)[-1]) if spec is not None else None
        paths = [value] if isinstance(value, str) else value
        if (attribute is not None and attribute.type == "target" and graph_path and isinstance(paths, (list, tuple))
                and any(isinstance(path, str) and path and not path.startswith("/") for path in paths)):
            anchor = Sdf.Path(f"{graph_path}/{node}")
            value = [str(Sdf.Path(str(path)).MakeAbsolutePath(anchor)) for path in paths]
        resolved[target] = value
    return resolved


def _legacy_values(graph: Graph, values: dict) -> dict:
    """*values* with those of Isaac 4.x grippers mapped to the legacy gripper's inputs (one line each)."""
    legacy = _legacy.get(graph, set())
    mapped: dict = {}
    by_node: dict[str, dict] = {}
    fields: dict[str, dict] = {}
    for target, value in values.items():
        node = _node_of(graph, target)
        field = _field_input(graph, target)
        if field is not None:
            fields.setdefault(node, {})[field[1]] = value
        elif node in legacy and ".inputs:" in str(target):
            by_node.setdefault(node, {})[str(target).rsplit(".inputs:", 1)[1]] = value
        else:
            mapped[target] = value
    for node, authored in by_node.items():
        mapped.update({f"{node}.inputs:{name}": value for name, value in og_legacy.values(node, authored, _warn).items()})
    for node, given in fields.items():   # merged into the fields the node already has
        handle = graph.document.node(node)
        before = json.loads(handle.inputs.get(MESSAGE_FIELDS, "{}")) if handle is not None else {}
        notes: list[str] = []
        mapped[f"{node}.inputs:{MESSAGE_FIELDS}"] = gather_message_fields({**before, **given}, f"node '{node}'", notes)
        for note in notes:
            _warn(note)
    return mapped


def _kept(graph: Graph, entries: list, ports: int = 2) -> list:
    """*entries* without those whose first *ports* items name a node ``_create`` dropped (named then)."""
    dropped = _dropped.get(graph, set())
    return [entry for entry in entries if not any(_node_of(graph, _port(part)) in dropped for part in entry[:ports])]


def _current(graph: Graph, values: list) -> list:
    """*values* without inputs the node's Isaac 4.x version had and later versions removed (one line each).

    ``usePath`` false meant "targetPrim, not robotPath": a robotPath authored in the same values goes too.
    """
    kept, ignore_robot_path = [], set()
    for target, value in values:
        node = _node_of(graph, _port(target))
        spec = _spec_of(graph, node)
        name = str(_port(target)).rsplit(".inputs:", 1)[-1]
        reason = REMOVED_INPUTS.get(spec.id, {}).get(name) if spec is not None else None
        if reason is None:
            kept.append((target, value))
            continue
        _warn(f"node '{node}' input 'inputs:{name}' = {value!r}: dropped: {reason}")
        if name == "usePath" and value is False:
            ignore_robot_path.add(node)
    dropped = [(t, v) for t, v in kept if _node_of(graph, _port(t)) in ignore_robot_path
               and str(_port(t)).endswith(".inputs:robotPath")]
    for target, value in dropped:
        _warn(f"node '{_node_of(graph, _port(target))}' input 'inputs:robotPath' = {value!r}: dropped: usePath is false")
    return [entry for entry in kept if entry not in dropped]


def _node_of(graph: Graph, port: str | Port) -> str:
    if isinstance(port, Port):
        return port.node
    path = next((p for p, g in _graphs.items() if g is graph), "")
    text = port[len(path) + 1:] if path and port.startswith(path + "/") else port
    return text.split(".", 1)[0]


def _source(graph: Graph, port: Any) -> str | Port:
    """A connection's source; Kit lets a constant be read from its ``inputs:value``: its output here; a generic
    subscriber's per-field output (Kit's ``outputs:data``) is read from its message by a ROS2MessageField node."""
    source = _port(port)
    if isinstance(source, Port):
        return source
    if ".outputs_" in source and ".outputs:" not in source:   # Kit's older spelling of a bundle output
        head, name = source.rsplit(".outputs_", 1)
        spec = _spec_of(graph, _node_of(graph, source))
        if spec is not None and spec.attribute(f"outputs:{name}") is not None:
            source = f"{head}.outputs:{name}"
    if ".outputs:" in source:
        node, name = _node_of(graph, source), source.rsplit(".outputs:", 1)[1]
        spec = _spec_of(graph, node)
        if spec is not None and spec.id in GENERIC_SUBSCRIBERS and spec.attribute(f"outputs:{name}") is None:
            return _message_field(graph, node, name)
    if ".inputs:" not in source:
        return source
    head, name = source.rsplit(".inputs:", 1)
    spec = _spec_of(graph, _node_of(graph, source))
    if spec is not None and any(output.name == name for output in spec.outputs):
        return f"{head}.outputs:{name}"
    return source


def _message_field(graph: Graph, subscriber: str, field: str) -> str:
    """The output of the ROS2MessageField node reading *field* of *subscriber*'s message (made on first use)."""
    name = f"{subscriber}_{field.replace(':', '_')}"
    if graph.document.node(name) is None:
        graph.node(name, MESSAGE_FIELD)
        graph.set(f"{name}.inputs:field", field)
        graph.connect(f"{subscriber}.outputs:message", f"{name}.inputs:message")
        _warn(f"node '{subscriber}' output 'outputs:{field}': Kit's per-field output read from outputs:message "
              f"by node '{name}' ({MESSAGE_FIELD})")
    return f"{name}.outputs:value"


def _spec_of(graph: Graph, node_name: str) -> NodeSpec | None:
    node = graph.document.node(node_name)
    node_type = graph.registry.get(node.type) if node is not None else None
    return node_type.spec if node_type is not None else None


def _declared(graph: Graph, port: str | Port) -> None:
    """``CREATE_ATTRIBUTES``: graphflow's node types declare every port; the one named must be there."""
    text = str(port)
    node_name = _node_of(graph, text)
    spec = _spec_of(graph, node_name)
    if spec is None:
        raise BadInput(f"og.Controller.edit: create_attributes {text}: no node '{node_name}' in the graph")
    group, _, name = text.rsplit(".", 1)[-1].partition(":")
    ports = spec.inputs if group == "inputs" else spec.outputs if group == "outputs" else ()
    if not any(attribute.name == name for attribute in ports):
        raise BadInput(f"og.Controller.edit: create_attributes {text}: {spec.id} has no {group or 'port'} "
                       f"'{name}' (graphflow's node types declare their ports; dynamic ones are not added)")


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
    if isinstance(port, og_lookup.Attribute):
        return port.get_path()
    if isinstance(port, tuple) and len(port) == 2:
        attribute, node = port
        if isinstance(node, str) and node.startswith("/"):   # ("inputs:x", "/ActionGraph/node")
            return f"{node}.{attribute}"
        return f"{_node_name(node)}.{attribute}"
    return port if isinstance(port, Port) else str(port)
