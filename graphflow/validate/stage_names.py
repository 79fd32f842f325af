"""Deep validation: a graph against the stage it names, and its exec wiring, without running anything.

``graphflow validate`` loads the document (schema, node types, connections)
and then calls ``deep_validate``:

* errors: the stage cannot be found or read (USD syntax errors as
  ``file:line:column``), or a prim path the graph names (gripper, robot,
  cubes, read/write nodes, checks) does not exist or is not the right kind
  (surface gripper, articulation, rigid body), or an articulation controller
  names a joint its articulation does not have, or a read/write node names
  an attribute the prim does not have ("did you mean ...");
* warnings: exec nodes no event can reach (they never run) and pure nodes
  whose outputs nothing reads.

Only usd-core is used (``graphflow.usd.physics_import``): no physics world is built.
"""
from __future__ import annotations

import difflib
import re
import warnings
from collections import deque
from typing import Any

from graphflow.document import GraphDocument, Problem
from graphflow.registry import Registry, default_registry

SURFACE_GRIPPER, ARTICULATION, RIGID_BODY, ANY_PRIM = "surface gripper", "articulation", "rigid body", "prim"
PRIM_OR_PROPERTY = "prim or property"      # a relationship target may be an attribute or another relationship
# (node type id, input) -> the kind of prim the input must name
PRIM_KINDS = {
    ("isaacsim.robot.surface_gripper.SurfaceGripper", "SurfaceGripper"): SURFACE_GRIPPER,
    ("graphflow.PickPlaceController", "robotPrim"): ARTICULATION,
    ("graphflow.PickPlaceController", "gripperPrim"): SURFACE_GRIPPER,
    ("graphflow.StackingController", "robotPrim"): ARTICULATION,
    ("graphflow.StackingController", "gripperPrim"): SURFACE_GRIPPER,
    ("graphflow.StackingController", "cubePrims"): RIGID_BODY,
    ("isaacsim.core.nodes.IsaacArticulationController", "targetPrim"): ARTICULATION,
    ("isaacsim.core.nodes.IsaacArticulationController", "robotPath"): ARTICULATION,
    ("graphflow.ReadJointState", "prim"): ARTICULATION,
    ("graphflow.LegacySurfaceGripper", "endEffectorPrim"): RIGID_BODY,
    ("omni.graph.action.AddPrimRelationship", "target"): PRIM_OR_PROPERTY,
}
# Target inputs Kit declares and ignores (ReadVariable/WriteVariable v2 "inputs:graph"): never checked on the stage
IGNORED_TARGETS = {("omni.graph.core.ReadVariable", "graph"), ("omni.graph.core.WriteVariable", "graph")}
ATTRIBUTE_NODES = ("omni.graph.nodes.ReadPrimAttribute", "omni.graph.nodes.WritePrimAttribute")
# Attributes the world reads or writes whether or not the stage authors them (graphflow.physics.world.ATTRIBUTES,
# named here so validation never loads the physics engine; a test keeps the two in step)
WORLD_BODY_ATTRIBUTES = ("xformOp:translate", "xformOp:orient", "physics:mass", "physics:velocity",
                         "physics:angularVelocity")
WORLD_JOINT_ATTRIBUTES = ("drive:linear:physics:targetPosition", "drive:angular:physics:targetPosition",
                          "drive:linear:physics:targetVelocity", "drive:angular:physics:targetVelocity",
                          "state:linear:physics:position", "state:angular:physics:position",
                          "state:linear:physics:velocity", "state:angular:physics:velocity",
                          "physics:lowerLimit", "physics:upperLimit")
LEGACY_GRIPPER = "graphflow.LegacySurfaceGripper"
_USD_LOCATION = re.compile(r"(?P<file>[^\s'(]+):(?P<line>\d+):(?P<column>\d+): (?P<message>.*)")


def usd_syntax_error(message: str) -> str:
    """USD's parse error as ``file:line:column: message`` without the parser's internal rule names."""
    found = _USD_LOCATION.search(message)
    if found is None:
        return message
    text = re.sub(r" matching \S+", "", found["message"]).strip().removesuffix(")").strip()
    return f"{found['file']}:{found['line']}:{found['column']}: {text}"


def deep_validate(document: GraphDocument, registry: Registry | None = None, *, allow_missing_assets: bool = False,
                  parsed: Any = None) -> tuple[list[Problem], list[Problem]]:
    """(errors, warnings) of a loaded document: its stage references, then its exec wiring.

    Inputs the importer kept although their prim's layer could not be opened
    (``settings.missingAssets``) are errors, or warnings with *allow_missing_assets*. *parsed*: the
    document's stage already opened and parsed (``validate.preflight.ParsedStage``), not read again.
    """
    registry = registry or default_registry()
    errors: list[Problem] = []
    missing = [Problem(document.source, entry["message"], node=entry["node"], attribute=entry["input"])
               for entry in document.settings.get("missingAssets", ())]
    reference = document.settings.get("stage")
    if reference is not None:
        skipped = {(problem.node, problem.attribute) for problem in missing}
        errors.extend(problem for problem in _stage_problems(document, registry, reference, parsed)
                      if (problem.node, problem.attribute) not in skipped)
    warnings = _wiring_warnings(document, registry) + unset_target_warnings(document, registry)
    if not allow_missing_assets:
        return missing + errors, warnings
    return errors, missing + warnings


def _spec_id(registry, node) -> str:
    node_type = registry.get(node.type)
    return node_type.spec.id if node_type is not None else node.type


def _paths(value) -> list[str]:
    if isinstance(value, str):
        return [value] if value else []
    return [v for v in value if isinstance(v, str) and v] if isinstance(value, (list, tuple)) else []


class _Stage:
    """What validation needs of a stage: prims, and usd-core's physics parse of it."""

    def __init__(self, usd_stage, description):
        self.usd = usd_stage
        self.description = description
        self.grippers = {g.path for g in description.surface_grippers}
        self.bodies = set(description.bodies)

    def prim(self, path: str):
        prim = self.usd.GetPrimAtPath(path) if path.startswith("/") else None
        return prim if prim is not None and prim.IsValid() else None

    def articulation(self, path: str):
        """The articulation *path* is, or is part of (a body, joint or prim under one), like the world's lookup."""
        probe = path
        while probe:
            for articulation in self.description.articulations:
                if probe == articulation.path or probe in articulation.bodies or probe in articulation.joints:
                    return articulation
            probe = probe.rsplit("/", 1)[0]
        return None

    def joint_names(self, articulation) -> list[str]:
        joints = self.description.joints
        return [path.rsplit("/", 1)[1] for path in articulation.joints
                if path in joints and joints[path].kind in ("revolute", "prismatic")]

    def kind_problem(self, path: str, kind: str) -> str | None:
        """Why *path* is not a prim of *kind* (None when it is)."""
        if kind == PRIM_OR_PROPERTY and path.startswith("/") and self.usd.GetObjectAtPath(path):
            return None
        prim = self.prim(path)
        if prim is None:
            close = difflib.get_close_matches(path, [str(p.GetPath()) for p in self.usd.Traverse()], n=1)
            return f"no prim {path} on the stage" + (f" (did you mean {close[0]}?)" if close else "")
        referenced = next((p for p in self._lineage(prim) if p.HasAuthoredReferences() or p.HasAuthoredPayloads()), None)
        note = (f" ({referenced.GetPath()} takes its content from a reference or payload: does that file open?)"
                if referenced is not None else "")
        if kind == SURFACE_GRIPPER and path not in self.grippers and prim.GetTypeName() != "IsaacSurfaceGripper":
            hint = f" (surface grippers on the stage: {', '.join(sorted(self.grippers))})" if self.grippers else ""
            return f"{path} is a {prim.GetTypeName() or 'typeless'} prim, not a surface gripper{hint or note}"
        if kind == ARTICULATION and self.articulation(path) is None:
            return f"{path} is not part of an articulation{note}"
        if kind == RIGID_BODY and path not in self.bodies:
            return f"{path} is not a rigid body{note}"
        return None

    @staticmethod
    def _lineage(prim):
        """The prim and its ancestors up to the root."""
        while prim.IsValid() and not prim.IsPseudoRoot():
            yield prim
            prim = prim.GetParent()


def _open(document: GraphDocument, reference: str):
    """(_Stage, None) or (None, the problem)."""
    from graphflow.usd.errors import StageError
    from graphflow.usd.physics_import import load_description, open_stage
    from graphflow.usd.resolver import resolve_stage

    try:
        path = resolve_stage(reference, document.base_dir)
    except StageError as error:
        return None, Problem(document.source, f"settings.stage: {error}")
    if not path.is_file():
        return None, Problem(document.source, f"settings.stage: {reference}: no such stage file ({path})")
    try:
        usd_stage, _label = open_stage(path)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")      # unsupported prims are the importer's to report, not validation's
            description = load_description(usd_stage)
    except StageError as error:
        return None, Problem(document.source, f"settings.stage: {usd_syntax_error(str(error))}")
    return _Stage(usd_stage, description), None


def _legacy_grippers(document: GraphDocument, registry) -> list[str]:
    """End effectors of LegacySurfaceGripper nodes: the gripper prims they create go under them at run time."""
    return [path for node in document.nodes if _spec_id(registry, node) == LEGACY_GRIPPER
            for path in _paths(node.inputs.get("endEffectorPrim", ()))]


def _stage_problems(document: GraphDocument, registry, reference: str, parsed: Any = None) -> list[Problem]:
    stage, problem = (_Stage(parsed.usd_stage, parsed.description), None) if parsed is not None \
        else _open(document, reference)
    if problem is not None:
        return [problem]
    source, problems = document.source, []
    for node in document.nodes:
        spec_id = _spec_id(registry, node)
        for name, value in node.inputs.items():
            kind = PRIM_KINDS.get((spec_id, name))
            node_type = registry.get(node.type)
            attribute = node_type.spec.attribute(f"inputs:{name}") if node_type is not None else None
            if kind is None and (attribute is None or attribute.type not in ("target", "path")
                                 or (spec_id, name) in IGNORED_TARGETS):
                continue
            for path in _paths(value):
                message = stage.kind_problem(path, kind or ANY_PRIM)
                if message is not None:
                    problems.append(Problem(source, message, node=node.name, attribute=f"inputs:{name}"))
        if spec_id == "isaacsim.core.nodes.IsaacArticulationController":
            problems.extend(_joint_problems(document, stage, node))
        if spec_id in ATTRIBUTE_NODES:
            problems.extend(_attribute_problems(document, stage, node))
    problems.extend(_check_problems(document, stage, _legacy_grippers(document, registry)))
    return problems


def _joint_problems(document, stage, node) -> list[Problem]:
    robot = node.inputs.get("robotPath") or next(iter(_paths(node.inputs.get("targetPrim", ()))), None)
    articulation = stage.articulation(robot) if robot else None
    if articulation is None:
        return []
    known = stage.joint_names(articulation)
    problems = []
    for name in node.inputs.get("jointNames", ()):
        if name not in known:
            close = difflib.get_close_matches(name, known, n=1)
            hint = f"did you mean {close[0]!r}?" if close else f"its joints: {', '.join(known)}"
            problems.append(Problem(document.source, f"articulation {articulation.path} has no joint {name!r} ({hint})",
                                    node=node.name, attribute="inputs:jointNames"))
    return problems


def _attribute_problems(document, stage, node) -> list[Problem]:
    name = node.inputs.get("name")
    path = node.inputs.get("primPath") if node.inputs.get("usePath") else next(iter(_paths(node.inputs.get("prim", ()))), None)
    prim = stage.prim(path) if path and name else None
    if prim is None or prim.HasAttribute(name) or (name in WORLD_BODY_ATTRIBUTES and path in stage.bodies) or (
            name in WORLD_JOINT_ATTRIBUTES and path in stage.description.joints):
        return []
    close = difflib.get_close_matches(name, prim.GetPropertyNames(), n=1)
    hint = f" (did you mean {close[0]!r}?)" if close else ""
    return [Problem(document.source, f"{path} has no attribute {name!r}{hint}", node=node.name, attribute="inputs:name")]


def _check_problems(document, stage, legacy_end_effectors) -> list[Problem]:
    problems = []
    for index, check in enumerate(document.checks, start=1):
        wanted = [(check[key], ANY_PRIM) for key in ("prim", "object") if key in check]
        wanted += [(path, ANY_PRIM) for path in check.get("prims", ())]
        gripper = check.get("gripper")
        made_at_run_time = gripper is not None and any(gripper.startswith(f"{end}/SurfaceGripper")
                                                       for end in legacy_end_effectors)
        if gripper is not None and not made_at_run_time:
            wanted.append((gripper, SURFACE_GRIPPER))
        for path, kind in wanted:
            message = stage.kind_problem(path, kind)
            if message is not None:
                problems.append(Problem(document.source, f"checks[{index}] ({check['check']}): {message}"))
    return problems


def _wiring_warnings(document: GraphDocument, registry) -> list[Problem]:
    """Exec nodes no event source reaches, and pure nodes whose outputs nothing reads."""
    types = {node.name: registry.get(node.type) for node in document.nodes}
    exec_edges: dict[str, list[str]] = {}
    read: set[str] = set()
    for connection in document.connections:
        read.add(connection.src_node)
        node_type = types.get(connection.dst_node)
        attribute = node_type.spec.attribute(connection.dst_attr) if node_type is not None else None
        if attribute is not None and attribute.is_execution:
            exec_edges.setdefault(connection.src_node, []).append(connection.dst_node)
    reached = {name for name, t in types.items() if t is not None and t.spec.is_event_source}
    queue = deque(reached)
    while queue:
        for target in exec_edges.get(queue.popleft(), ()):
            if target not in reached:
                reached.add(target)
                queue.append(target)
    source, found = document.source, []
    for node in document.nodes:
        node_type = types[node.name]
        if node_type is None:
            continue
        spec = node_type.spec
        if spec.exec_inputs and not spec.is_event_source and node.name not in reached:
            found.append(Problem(source, "never runs: no event source reaches its exec inputs", node=node.name))
        elif spec.is_pure and spec.outputs and node.name not in read:
            found.append(Problem(source, "computes for nothing: no connection reads its outputs", node=node.name))
    return found


PRIM_VALUE_NODES = frozenset({"omni.graph.nodes.ConstantPrims", "omni.graph.nodes.GetPrimPaths",
                              "omni.graph.nodes.FindPrims"})   # their targets are values: empty is a value


def unset_target_warnings(document: GraphDocument, registry: Registry | None = None) -> list[Problem]:
    """Required ``target`` inputs neither authored nor connected: the node has no prim to work on.

    Required: not optional, not "(unset: ...)" in its description, and no ``...Path`` input of the same
    node given instead (``robotPath`` for ``targetPrim``). Nodes whose targets are plain values
    (``ConstantPrims`` and the like) are left alone.
    """
    registry = registry or default_registry()
    connected = {(c.dst_node, c.dst_attr) for c in document.connections}
    found = []
    for node in document.nodes:
        node_type = registry.get(node.type)
        if node_type is None or node_type.spec.id in PRIM_VALUE_NODES:
            continue

        def given(name: str) -> bool:
            return bool(node.inputs.get(name)) or (node.name, f"inputs:{name}") in connected

        inputs = node_type.spec.inputs
        if any(a.name.endswith("Path") and given(a.name) for a in inputs):
            continue
        for attribute in inputs:
            if (attribute.type == "target" and not attribute.optional and "(unset:" not in attribute.description
                    and attribute.default is None and not given(attribute.name)):
                found.append(Problem(document.source, "required target is unset (neither authored nor connected): "
                                     "the node has no prim to work on and fails at its first compute",
                                     node=node.name, attribute=f"inputs:{attribute.name}"))
    return found
