"""Parts of an Isaac graph beyond its nodes: graph variables, node versions, several graphs in one file.

* Graph variables: Kit stores each as an attribute ``graph:variable:NAME`` on
  the OmniGraph prim (its USD type is the variable's type, its value the
  default; a ``rel`` for a target variable). They become document variables.
* Versions: a file may name any ``node:typeVersion``. A version graphflow does
  not implement loads as graphflow's version of the node: the ports that moved
  between versions (taken from the ``updateNodeVersion`` code of Isaac's
  nodes) are mapped, a newer version is loaded when its ports fit, and one line
  says which version was loaded and what was mapped.
* Several graphs: Kit evaluates every graph of a stage, so a file with several
  imports them all into one document; node and variable names get the graph
  prim's name in front so they stay unique.
"""
from __future__ import annotations

VARIABLE_PREFIX = "graph:variable:"
# nodes whose inputs:path may name a node of their graph: imported as that node's (prefixed) name
NODE_PATH_READERS = ("omni.graph.nodes.ReadOmniGraphValue",)
VARIABLE_NODES = ("omni.graph.core.ReadVariable", "omni.graph.core.WriteVariable",
                  "omni.graph.action.OnVariableChange")

# USD value type name -> graphflow type name (graphflow.types)
_ROLES = {"vector": "vector", "point": "point", "normal": "normal", "color": "color", "texCoord": ""}
_SCALARS = ("bool", "uchar", "int", "int64", "uint", "uint64", "float", "double", "half", "token", "string")

# (node type id, authored version) -> {old port: new port, or None when the port was removed}
# from Isaac's updateNodeVersion code (isaacsim.ros2.nodes, isaacsim.sensors.physx)
PORT_CHANGES: dict[tuple[str, int], dict[str, str | None]] = {
    ("isaacsim.ros2.bridge.ROS2SubscribeJointState", 1): {"inputs:targetPrim": None},
    ("omni.graph.nodes.Timer", 1): {"outputs:alpha": "outputs:value"},     # Kit's node library, Timer v1 and v2
}


def graphflow_type(usd_type: str) -> str | None:
    """graphflow's name for a USD value type (``double3`` -> ``double[3]``, ``quatd[]`` -> ``quatd[4][]``), or None."""
    array = usd_type.endswith("[]")
    base = usd_type[:-2] if array else usd_type
    suffix = "[]" if array else ""
    if base in _SCALARS:
        return base + suffix
    if base == "asset":
        return "path" + suffix
    if base.startswith("quat") and len(base) == 5:
        return f"{base}[4]{suffix}"
    if base.startswith("matrix") and base.endswith("d") and base[6:-1].isdigit():
        size = int(base[6:-1])
        return f"matrixd[{size * size}]{suffix}"
    if base[-1].isdigit() and base[:-1] in ("double", "float", "half", "int"):   # double3, int2
        return f"{base[:-1]}[{base[-1]}]{suffix}"
    if base[-2:-1].isdigit() and base[-1] in "dfh" and base[:-2] in _ROLES:      # vector3d, point3f, texCoord2f
        components, letter, role = base[-2], base[-1], _ROLES[base[:-2]]
        scalar = {"d": "double", "f": "float", "h": "half"}[letter]
        return f"{role}{letter}[{components}]{suffix}" if role else f"{scalar}[{components}]{suffix}"
    return None


def graph_variables(graph_prim, label: str, value_of, warnings: list[str]) -> list[dict]:
    """The graph's variables as document entries (name, type, default), one line per variable not brought over."""
    variables = []
    for prop in graph_prim.GetProperties():
        name = prop.GetName()
        if not name.startswith(VARIABLE_PREFIX):
            continue
        short = name[len(VARIABLE_PREFIX):]
        where = f"{label}: {graph_prim.GetPath()}: graph variable '{short}'"
        if hasattr(prop, "GetTargets"):
            targets = [str(path) for path in prop.GetTargets()]
            variables.append({"name": short, "type": "target", **({"default": targets} if targets else {})})
            continue
        type_name = graphflow_type(str(prop.GetTypeName()))
        if type_name is None:
            warnings.append(f"{where}: USD type {prop.GetTypeName()} has no graphflow equivalent; dropped")
            continue
        entry = {"name": short, "type": type_name}
        value = value_of(prop)
        if value is not None:
            entry["default"] = value
        variables.append(entry)
    return variables


def map_version(spec, version: int, ports: set[str], where: str, warnings: list[str]) -> dict[str, str | None]:
    """How the ports of *version* map onto graphflow's node (``{old: new or None}``), with one line saying so.

    *ports* are the node's authored and connected ports (``inputs:x``, ``outputs:y``).
    """
    changes = dict(PORT_CHANGES.get((spec.id, version), {}))
    unknown = sorted(port for port in ports if port not in changes and spec.attribute(port) is None)
    relation = "newer than" if version > spec.version else "older than"
    mapped = [f"{old} -> {new}" if new else f"{old} removed" for old, new in sorted(changes.items()) if old in ports]
    line = f"{where}: typeVersion {version} of {spec.id} is {relation} graphflow's {spec.version}: loaded as version {spec.version}"
    if mapped:
        line += f" (mapped: {', '.join(mapped)})"
    if unknown:
        line += f"; ports not in version {spec.version}: {', '.join(unknown)} (dropped)"
    elif version > spec.version:
        line += " (its ports all exist there)"
    warnings.append(line)
    return changes


def graph_prefixes(graph_paths: list[str]) -> dict[str, str]:
    """The name prefix of each graph's nodes and variables: its prim name, or its whole path when names repeat."""
    names = [path.rsplit("/", 1)[-1] for path in graph_paths]
    return {path: (name if names.count(name) == 1 else path.strip("/").replace("/", "_")) + "_"
            for path, name in zip(graph_paths, names)}


def prefixed(part: dict, prefix: str) -> dict:
    """One imported graph's nodes, connections, ui, variables and missing assets with *prefix* on every name."""
    variables = {v["name"]: prefix + v["name"] for v in part["variables"]}
    nodes = []
    for node in part["nodes"]:
        node = {**node, "name": prefix + node["name"]}
        inputs = node.get("inputs", {})
        if node["type"] in VARIABLE_NODES and inputs.get("variableName") in variables:
            node["inputs"] = {**inputs, "variableName": variables[inputs["variableName"]]}
        if node["type"] in NODE_PATH_READERS and inputs.get("path") and not str(inputs["path"]).startswith("/"):
            node["inputs"] = {**inputs, "path": prefix + inputs["path"]}   # the node it names got the prefix too
        nodes.append(node)
    return {
        "nodes": nodes,
        "connections": [{"src": prefix + c["src"], "dst": prefix + c["dst"]} for c in part["connections"]],
        "ui": {prefix + name: value for name, value in part["ui"].items()},
        "variables": [{**v, "name": variables[v["name"]]} for v in part["variables"]],
        "missingAssets": [{**m, "node": prefix + m["node"]} for m in part["missingAssets"]],
    }


# graph instancing (omni.usd.schema.omnigraph): prims with OmniGraphAPI name graphs in their omniGraphs relationship
INSTANCE_TOKEN = "_OMNI_GRAPH_TARGET"     # Kit replaces it in prim paths with the instance's target at run time
INSTANCES_RELATIONSHIP = "omniGraphs"
GRAPH_TARGET_NODES = ("omni.graph.nodes.GraphTarget", "omni.graph.nodes.GetGraphTargetPrim",
                      "omni.graph.nodes.GetGraphTargetId")


def graph_targets(stage, graph_prim, label: str, value_of, warnings: list[str]) -> list[str]:
    """The prims a graph runs for, as Kit evaluates it: each prim that names it in its omniGraphs relationship
    (an instanced graph: evaluationMode Automatic or Instanced), else the graph prim itself (Standalone, or
    Automatic without instances). An Instanced graph no prim names never runs: no target, with a line."""
    graph_path = str(graph_prim.GetPath())
    mode = value_of(graph_prim.GetAttribute("evaluationMode")) or "Automatic"
    instances = [str(prim.GetPath()) for prim in stage.Traverse()
                 if prim.HasRelationship(INSTANCES_RELATIONSHIP)
                 and graph_path in (str(t) for t in prim.GetRelationship(INSTANCES_RELATIONSHIP).GetTargets())]
    where = f"{label}: {graph_path}"
    if mode == "Standalone":
        if instances:
            warnings.append(f"{where}: evaluationMode Standalone: the prims naming it ({', '.join(instances)}) "
                            "are ignored, as Kit does")
        return [graph_path]
    if instances:
        warnings.append(f"{where}: an instanced graph, imported once per target prim: {', '.join(instances)}")
        return instances
    if mode == "Instanced":
        warnings.append(f"{where}: evaluationMode Instanced but no prim names it in omniGraphs, so Kit never "
                        "evaluates it; not imported")
        return []
    return [graph_path]


def bind_target(part: dict, target: str) -> dict:
    """One graph's parts run for *target*: the instance token in input paths replaced by it, and the graph-target
    nodes told it (their targetPath input)."""
    def bound(value):
        if isinstance(value, str):      # as a path (/_OMNI_GRAPH_TARGET/child) or a bare token
            return value.replace("/" + INSTANCE_TOKEN, target).replace(INSTANCE_TOKEN, target)
        if isinstance(value, (list, tuple)):
            return [bound(item) for item in value]
        return value

    nodes = []
    for node in part["nodes"]:
        inputs = {name: bound(value) for name, value in node.get("inputs", {}).items()}
        if node["type"] in GRAPH_TARGET_NODES:
            inputs["targetPath"] = target
        nodes.append({**node, "inputs": inputs} if inputs else node)
    return {**part, "nodes": nodes}
