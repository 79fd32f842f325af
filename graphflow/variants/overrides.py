"""Overrides: change a graph's node inputs or its stage's attributes for one run, without editing files.

Two kinds of target, told apart by the leading slash:

* ``NODE.INPUT`` (``gripper.forceLimit``): an authored node input. The result
  is a new immutable ``GraphDocument`` checked exactly as the file itself
  (type, range, the node type's own ``validate``).
* ``/Prim/Path.attribute`` (``/World/Cube.physics:mass``): an attribute of the
  USD stage, written on the opened stage's *session layer* before the physics
  world is parsed from it, so the world is exactly what a stage authored with
  that value would give. Values are in the attribute's USD units (degrees for
  angular drive targets and limits) and typed by the attribute's USD type.

A ``PoseJitter`` (from randomization, ``graphflow.variants.randomize``) moves a prim
by an offset added to its authored ``xformOp:translate`` and turns it about
its parent's Z axis (``xformOp:rotateZ:graphflowYaw``, inserted right after
the translate op). Every problem is an ``OverrideError`` whose one line
names the override.
"""
from __future__ import annotations

import dataclasses
import difflib
import json
import math
import re
from dataclasses import dataclass
from typing import Any, Iterable, Sequence

from graphflow.compiler import compile
from graphflow.errors import BadInput
from graphflow.model import GraphDocument, GraphError, frozen_mapping
from graphflow.types import TypeMismatch

YAW_OP_SUFFIX = "graphflowYaw"
# USD physics and Isaac attributes (last name part) that the schemas define as non-negative
NON_NEGATIVE = frozenset({"mass", "density", "stiffness", "damping", "maxForce", "size", "radius", "height",
                          "maxGripDistance", "coaxialForceLimit", "shearForceLimit", "retryInterval",
                          "breakForce", "breakTorque", "staticFriction", "dynamicFriction"})
_NODE_TARGET = re.compile(r"^([A-Za-z0-9_-]+)\.(?:inputs:)?([A-Za-z_][A-Za-z0-9_:]*)$")
_STAGE_TARGET = re.compile(r"^(/[^.\s]*[^/.\s])\.([A-Za-z_][A-Za-z0-9_:]*)$")


class OverrideError(BadInput):
    """An override that cannot be applied; the message is one line naming it."""


@dataclass(frozen=True)
class Override:
    """Set ``target`` (``NODE.INPUT`` or ``/Prim.attribute``) to ``value``; ``origin`` names it in messages."""

    target: str
    value: Any
    origin: str = ""
    text: str | None = dataclasses.field(default=None, compare=False)   # the value as typed, for string inputs

    @property
    def on_stage(self) -> bool:
        return self.target.startswith("/")

    @property
    def label(self) -> str:
        return self.origin or f"--set {self.target}={json.dumps(self.value)}"

    def parts(self) -> tuple[str, str]:
        """(node name, input name) or (prim path, attribute name)."""
        match = (_STAGE_TARGET if self.on_stage else _NODE_TARGET).match(self.target)
        if match is None:
            raise OverrideError(f"{self.label}: expected NODE.INPUT or /Prim/Path.attribute, got {self.target!r}")
        return match.group(1), match.group(2)


@dataclass(frozen=True)
class PoseJitter:
    """Move a prim by ``offset`` (m, parent frame, added to its translate) and yaw it by ``yaw_degrees``."""

    prim: str
    offset: tuple[float, float, float] = (0.0, 0.0, 0.0)
    yaw_degrees: float = 0.0
    origin: str = ""

    @property
    def on_stage(self) -> bool:
        return True

    @property
    def label(self) -> str:
        return self.origin or f"pose of {self.prim}"


def parse_set(text: str) -> Override:
    """``TARGET=VALUE`` from the command line; VALUE is JSON, or a bare string when it is not JSON."""
    target, separator, raw = text.partition("=")
    if not separator or not target:
        raise OverrideError(f"--set {text}: expected NODE.INPUT=VALUE or /Prim/Path.attribute=VALUE")
    try:
        value = json.loads(raw)
    except json.JSONDecodeError:
        value = raw
    override = Override(target.strip(), value, origin=f"--set {text}", text=raw)
    override.parts()
    return override


# ------------------------------------------------------------------ node inputs

def apply_node_overrides(document: GraphDocument, edits: Iterable[Override | PoseJitter]) -> GraphDocument:
    """A new document with the overridden node inputs (stage edits are left out), checked as the file is; the
    old one is unchanged."""
    overrides = [edit for edit in edits if isinstance(edit, Override) and not edit.on_stage]
    if not overrides:
        return document
    from graphflow.registry import default_registry

    registry = default_registry()
    connected = {(c.dst_node, c.dst_attr) for c in document.connections}
    inputs: dict[str, dict[str, Any]] = {node.name: dict(node.inputs) for node in document.nodes}
    for override in overrides:
        node_name, input_name = override.parts()
        node = document.node(node_name)
        if node is None:
            hint = _hint(node_name, inputs)
            raise OverrideError(f"{override.label}: the graph has no node {node_name!r}{hint}")
        node_type = registry.get(node.type)
        attribute = node_type.spec.attribute(f"inputs:{input_name}") if node_type else None
        if attribute is None:
            names = [a.name.removeprefix("inputs:") for a in node_type.spec.inputs] if node_type else []
            raise OverrideError(f"{override.label}: node '{node_name}' ({node.type}) has no input "
                                f"{input_name!r}{_hint(input_name, names)}")
        if attribute.is_execution:
            raise OverrideError(f"{override.label}: '{input_name}' is an execution input; it takes connections")
        if (node_name, f"inputs:{input_name}") in connected:
            raise OverrideError(f"{override.label}: node '{node_name}' input '{input_name}' is connected, "
                                "so a value set on it would be ignored")
        value: Any = override.value
        if not isinstance(value, str) and override.text is not None and attribute.type in ("string", "token"):
            value = override.text   # --set print.text=42 means the text "42"
        try:
            attribute.check(value)
        except TypeMismatch as error:
            raise OverrideError(f"{override.label}: node '{node_name}' input '{input_name}': {error}") from None
        inputs[node_name][input_name] = value
    nodes = tuple(dataclasses.replace(node, inputs=frozen_mapping(inputs[node.name])) for node in document.nodes)
    changed = dataclasses.replace(document, nodes=nodes)
    try:
        compile(changed, registry)   # checked exactly as the file is
    except GraphError as error:
        labels = ", ".join(o.label for o in overrides)
        raise OverrideError(f"{labels}: {error.problems[0]}") from None
    return changed


def _hint(name: str, candidates) -> str:
    close = difflib.get_close_matches(name, list(candidates), n=1)
    return f" (did you mean {close[0]!r}?)" if close else ""


# ------------------------------------------------------------------ stage attributes

def apply_stage_overrides(stage, edits: Sequence[Override | PoseJitter]) -> None:
    """Author *edits* on the stage's session layer (the files on disk are never touched)."""
    from pxr import Usd

    with Usd.EditContext(stage, stage.GetSessionLayer()):
        for edit in edits:
            if isinstance(edit, PoseJitter):
                _apply_pose(stage, edit)
            else:
                _apply_attribute(stage, edit)


def _prim(stage, path: str, label: str):
    prim = stage.GetPrimAtPath(path)
    if not prim:
        paths = [str(p.GetPath()) for p in stage.Traverse()]
        raise OverrideError(f"{label}: the stage has no prim {path}{_hint(path, paths)}")
    return prim


def _apply_attribute(stage, override: Override) -> None:
    path, name = override.parts()
    prim = _prim(stage, path, override.label)
    attribute = prim.GetAttribute(name)
    if not attribute:
        names = [a.GetName() for a in prim.GetAttributes()]
        raise OverrideError(f"{override.label}: prim {path} has no attribute {name!r}{_hint(name, names)}")
    try:
        value = _usd_value(attribute.GetTypeName(), override.value)
        if name.rsplit(":", 1)[-1] in NON_NEGATIVE and any(v < 0 for v in _flat_numbers(value)):
            raise TypeMismatch(f"must not be negative, got {override.value!r}")
    except TypeMismatch as error:
        raise OverrideError(f"{override.label}: {path}.{name} ({attribute.GetTypeName()}): {error}") from None
    if not attribute.Set(value):
        raise OverrideError(f"{override.label}: {path}.{name} could not be set to {override.value!r}")


def _apply_pose(stage, jitter: PoseJitter) -> None:
    from pxr import Gf, UsdGeom

    prim = _prim(stage, jitter.prim, jitter.label)
    xformable = UsdGeom.Xformable(prim)
    if not xformable:
        raise OverrideError(f"{jitter.label}: {jitter.prim} is not transformable (not an Xformable prim)")
    ops = list(xformable.GetOrderedXformOps())
    if ops and ops[0].GetOpType() != UsdGeom.XformOp.TypeTranslate:
        raise OverrideError(f"{jitter.label}: the xformOpOrder of {jitter.prim} must start with a translate op "
                            f"to move it (it starts with {ops[0].GetOpName()})")
    if ops:
        translate = ops[0]
        current = translate.Get() or (0.0, 0.0, 0.0)
        moved = [float(c) + d for c, d in zip(current, jitter.offset)]
        translate.Set(Gf.Vec3d(*moved) if isinstance(current, tuple) else type(current)(*moved))
        rest = ops[1:]
    else:
        translate = xformable.AddTranslateOp(UsdGeom.XformOp.PrecisionDouble)
        translate.Set(Gf.Vec3d(*jitter.offset))
        rest = []
    if jitter.yaw_degrees:
        yaw = xformable.AddRotateZOp(UsdGeom.XformOp.PrecisionDouble, YAW_OP_SUFFIX)
        yaw.Set(float(jitter.yaw_degrees))
        xformable.SetXformOpOrder([translate, yaw, *rest])


def _usd_value(type_name, value):
    """*value* (JSON) as a value of the USD type *type_name*; raise TypeMismatch saying what was expected."""
    from pxr import Gf, Sdf

    scalar = str(type_name.scalarType)
    if type_name.isArray:
        if not isinstance(value, list):
            raise TypeMismatch(f"expected a list, got {value!r}")
        return [_usd_scalar(scalar, item, Gf, Sdf) for item in value]
    return _usd_scalar(scalar, value, Gf, Sdf)


def _usd_scalar(scalar: str, value, Gf, Sdf):
    if scalar == "bool":
        if not isinstance(value, bool):
            raise TypeMismatch(f"expected true or false, got {value!r}")
        return value
    if scalar in ("int", "int64", "uint", "uint64", "uchar"):
        if isinstance(value, bool) or not isinstance(value, int):
            raise TypeMismatch(f"expected an integer, got {value!r}")
        if scalar.startswith("u") and value < 0:
            raise TypeMismatch(f"expected a non-negative integer, got {value}")
        return value
    if scalar in ("half", "float", "double", "timecode"):
        return _number(value)
    if scalar in ("token", "string"):
        if not isinstance(value, str):
            raise TypeMismatch(f"expected a string, got {value!r}")
        return value
    if scalar == "asset":
        if not isinstance(value, str):
            raise TypeMismatch(f"expected an asset path string, got {value!r}")
        return Sdf.AssetPath(value)
    if scalar.startswith("quat"):
        x, y, z, w = _numbers(value, 4, "a quaternion [x, y, z, w]")
        if not math.hypot(x, y, z, w) > 0:
            raise TypeMismatch("a quaternion must not be zero")
        quat = {"quatd": Gf.Quatd, "quatf": Gf.Quatf, "quath": Gf.Quath}[scalar]
        return quat(w, x, y, z)
    size = re.search(r"([234])[dfhi]?$", scalar)
    if size and not scalar.startswith("matrix"):
        numbers = _numbers(value, int(size.group(1)), f"{size.group(1)} numbers")
        if scalar.endswith("i"):
            if not all(float(n).is_integer() for n in numbers):
                raise TypeMismatch(f"expected {size.group(1)} integers, got {value!r}")
            return tuple(int(n) for n in numbers)
        return tuple(numbers)
    raise TypeMismatch(f"attributes of type {scalar} cannot be overridden")


def _flat_numbers(value) -> list[float]:
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        return [value]
    if isinstance(value, (list, tuple)):
        return [n for item in value for n in _flat_numbers(item)]
    return []


def _number(value) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise TypeMismatch(f"expected a number, got {value!r}")
    if not math.isfinite(value):
        raise TypeMismatch(f"expected a finite number, got {value!r}")
    return float(value)


def _numbers(value, count: int, what: str) -> list[float]:
    if not isinstance(value, (list, tuple)) or len(value) != count:
        raise TypeMismatch(f"expected {what}, got {value!r}")
    return [_number(v) for v in value]


# ------------------------------------------------------------------ scenarios

@dataclass(frozen=True)
class Variant:
    """A document with its node overrides applied, plus the stage edits its world is built with."""

    document: GraphDocument
    stage_edits: tuple = ()
    drawn: tuple = ()      # what --randomize drew, as JSON records (the trace header's ``randomized``)

    def create_world(self, *, gui: bool = False):
        """The document's world with the stage edits on the session layer (as ``runtime.create_world_for``)."""
        from graphflow.runtime import create_world, create_world_for

        if not self.stage_edits:
            return create_world_for(self.document, gui=gui)
        stage = self.open_stage()
        from graphflow.usd.errors import StageError

        settings = self.document.settings
        try:
            return create_world(stage, time_step=settings.get("timeStep"), substeps=settings.get("substeps"),
                                gui=gui)
        except StageError as error:
            labels = ", ".join(edit.label for edit in self.stage_edits)
            raise OverrideError(f"{labels}: the stage with these overrides is not valid: {error}") from None

    def open_stage(self):
        """The document's stage, freshly opened, with the stage edits applied."""
        stage_reference = self.document.settings.get("stage")
        if stage_reference is None:
            raise OverrideError(f"{self.stage_edits[0].label}: the graph names no stage (settings.stage)")
        from graphflow.usd.opening import open_composed
        from graphflow.usd.resolver import resolve_stage

        path = resolve_stage(stage_reference, self.document.base_dir)
        stage = open_composed(path)
        if stage is None:
            raise OverrideError(f"{path}: not a USD stage")
        apply_stage_overrides(stage, self.stage_edits)
        return stage


def make_variant(document: GraphDocument, edits: Sequence[Override | PoseJitter]) -> Variant:
    """Apply node overrides now and keep the stage edits for the world (checked here against the stage)."""
    changed = apply_node_overrides(document, edits)
    stage_edits = tuple(e for e in edits if e.on_stage)
    return Variant(changed, stage_edits)
