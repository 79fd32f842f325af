"""Kit's dynamic bundle ports, brought over as fixed-port nodes on import.

Some bundle nodes of omni.graph.nodes grow one port per attribute in Kit;
graphflow node types have fixed ports, so the importer rewrites them with
bundle nodes that exist:

* a connection from a dynamic output of ReadPrimAttributes, ReadPrim or
  ExtractBundle (``outputs:size``) reads the node's bundle through an
  ExtractAttribute node ``NODE_size`` (attrName ``size``);
* the dynamic inputs of BundleConstructor (connected or authored) and the
  connected dynamic inputs of WritePrim become one InsertAttribute node each
  (``NODE_size``, outputAttrName ``size``), chained: BundleConstructor's
  bundle runs through the chain and its readers read the chain's end; the
  chain's end feeds WritePrim's ``attributes``. Kit writes only connected
  inputs of WritePrim, so an authored, unconnected one is named and dropped.

Each added node is one line naming what it stands for. Kit keeps a bundle
connection as a relationship on the input, targeting the source node's output
bundle (a child prim ``NODE/outputs_NAME`` in older files, the property
``NODE.outputs:NAME`` in newer ones): ``input_sources`` reads those as
connections.
"""
from __future__ import annotations

import re

EXTRACT, INSERT = "omni.graph.nodes.ExtractAttribute", "omni.graph.nodes.InsertAttribute"
# node type -> the bundle output its dynamic outputs are attributes of
DYNAMIC_OUTPUTS = {"omni.graph.nodes.ReadPrimAttributes": "outputs:primBundle",
                   "omni.graph.nodes.ReadPrim": "outputs:primBundle",
                   "omni.graph.nodes.ExtractBundle": "outputs:passThrough"}
CONSTRUCTOR, WRITER = "omni.graph.nodes.BundleConstructor", "omni.graph.nodes.WritePrim"
DYNAMIC_INPUTS = (CONSTRUCTOR, WRITER)


def input_sources(prim, spec):
    """(input name, source property paths) of a node prim's connected inputs, bundle relationships included."""
    for prop in prim.GetAuthoredProperties():
        name = prop.GetName()
        if not name.startswith("inputs:"):
            continue
        if not hasattr(prop, "GetTargets"):
            yield name, prop.GetConnections()
            continue
        attribute = spec.attribute(name) if spec is not None else None
        if attribute is None or not attribute.attr_type.is_bundle:
            continue
        sources = []
        for target in prop.GetTargets():
            if target.IsPropertyPath():
                sources.append(target)
            elif target.name.startswith("outputs_"):
                sources.append(target.GetParentPath().AppendProperty("outputs:" + target.name[len("outputs_"):]))
            else:
                sources.append(target)      # not an output bundle: the caller names it as dropped
        yield name, sources


def _node_name(base: str, attribute: str, taken: set[str]) -> str:
    name = f"{base}_{re.sub(r'[^A-Za-z0-9_]', '_', attribute)}"
    unique, index = name, 1
    while unique in taken:
        index += 1
        unique = f"{name}_{index}"
    taken.add(unique)
    return unique


def expand(node_prims, kept: dict, registry, value_of, where: str, warnings: list[str]) -> tuple[list, list, dict]:
    """(nodes, connections, renames) standing for the dynamic bundle ports of the kept nodes.

    *renames* maps ``(node, port)`` to the ``node.port`` that takes its place, for the importer's
    connection pass; *value_of* reads an attribute's composed value."""
    nodes: list[dict] = []
    connections: list[dict] = []
    renames: dict = {}
    taken = set(kept)
    types = {prim.GetName(): kept[prim.GetName()].spec for prim in node_prims if prim.GetName() in kept}
    for prim in node_prims:
        for attribute in prim.GetAttributes():
            for source in attribute.GetConnections():
                node, port = source.GetPrimPath().name, source.name
                spec = types.get(node)
                if spec is None or spec.id not in DYNAMIC_OUTPUTS or spec.attribute(port) is not None \
                        or not port.startswith("outputs:") or (node, port) in renames:
                    continue
                name = port.split(":", 1)[1]
                added = _node_name(node, name, taken)
                nodes.append({"name": added, "type": EXTRACT, "inputs": {"attrName": name}})
                connections.append({"src": f"{node}.{DYNAMIC_OUTPUTS[spec.id]}", "dst": f"{added}.inputs:data"})
                renames[(node, port)] = f"{added}.outputs:output"
                warnings.append(f"{where}: node '{node}' output '{port}' (a Kit dynamic bundle output) read through "
                                f"a new {EXTRACT} node '{added}'")
        spec = types.get(prim.GetName())
        if spec is not None and spec.id in DYNAMIC_INPUTS:
            _chain(prim, spec, value_of, taken, where, warnings, nodes, connections, renames)
    for node in nodes:
        kept[node["name"]] = registry.get(node["type"])
    return nodes, connections, renames


def _chain(prim, spec, value_of, taken: set[str], where: str, warnings: list[str], nodes, connections, renames):
    """One InsertAttribute node per dynamic input of a BundleConstructor or WritePrim, chained."""
    owner = prim.GetName()
    previous = f"{owner}.outputs:bundle" if spec.id == CONSTRUCTOR else None
    for attribute in prim.GetAttributes():
        port = attribute.GetName()
        if not port.startswith("inputs:") or spec.attribute(port) is not None:
            continue
        name = port.split(":", 1)[1]
        connected = bool(attribute.GetConnections())
        value = None if connected else value_of(attribute)
        if not connected and (value is None or spec.id == WRITER):
            if value is not None:
                warnings.append(f"{where}: node '{owner}' input '{port}' = {value!r} is not connected: Kit's WritePrim "
                                "writes connected inputs only; dropped")
            continue
        added = _node_name(owner, name, taken)
        entry: dict = {"name": added, "type": INSERT, "inputs": {"outputAttrName": name}}
        if connected:
            renames[(owner, port)] = f"{added}.inputs:attrToInsert"
        else:
            entry["inputs"]["attrToInsert"] = value
        nodes.append(entry)
        if previous is not None:
            connections.append({"src": previous, "dst": f"{added}.inputs:data"})
        previous = f"{added}.outputs:data"
        warnings.append(f"{where}: node '{owner}' input '{port}' (a Kit dynamic bundle input) inserted into its "
                        f"bundle by a new {INSERT} node '{added}'")
    if spec.id == CONSTRUCTOR and previous != f"{owner}.outputs:bundle":
        renames[(owner, "outputs:bundle")] = previous
    elif spec.id == WRITER and previous is not None:
        connections.append({"src": previous, "dst": f"{owner}.inputs:attributes"})
