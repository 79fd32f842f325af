"""A prim's attributes as a bundle: what Kit's ReadPrims nodes put in a prim's child bundle.

Every attribute with a value (authored or the schema's fallback, as composed on
the stage) with its USD type written as a graphflow type (``point3f[]`` ->
``pointf[3][]``, ``matrix4d`` -> ``matrixd[16]``: ``graph_parts.graphflow_type``);
types graphflow has no form for (dictionaries, opaque values) are left out.
Worlds pass the values they simulate (a body's pose, a joint's state) in
``live`` so a bundle read while running shows the physics, not the file. The
prim's world transform is ``worldMatrix`` (row-vector convention, translation
in the last row, as USD and Kit); ``bounding_box`` adds Kit's
``bboxMinCorner``/``bboxMaxCorner`` (the prim's untransformed extent, children
included) and ``bboxTransform`` (the matrix of that box, identity for an
untransformed bound).
"""
from __future__ import annotations

from typing import Any, Callable

from graphflow.bundles import WORLD_MATRIX, Bundle, BundleAttribute
from graphflow.poses import Pose
from graphflow.usd.graph_parts import graphflow_type


def prim_bundle(prim, *, live: Callable[[str], Any], world_pose: Pose | None, bounding_box: bool = False,
                time: float | None = None) -> Bundle:
    """The bundle of one prim. ``live(name)`` returns the simulated value of an attribute or None (use USD's,
    at time code *time*; None: the default time); ``world_pose`` is the prim's current world pose (None: USD's
    transform)."""
    return PrimReader().read(prim, live=live, world_pose=world_pose, bounding_box=bounding_box, time=time)


class PrimReader:
    """``prim_bundle`` keeping what USD composed for each prim (its attributes, transform and extent), which
    does not change while a world runs: a prim read every tick costs its live values and one matrix product."""

    def __init__(self):
        self._composed: dict[tuple[str, float | None], tuple] = {}
        self._boxes: dict[str, list[BundleAttribute]] = {}

    def read(self, prim, *, live: Callable[[str], Any], world_pose: Pose | None, bounding_box: bool = False,
             time: float | None = None) -> Bundle:
        key = (str(prim.GetPath()), time)
        composed = self._composed.get(key)
        if composed is None:
            composed = self._composed[key] = _composed(prim, time)
        fixed, transform = composed
        attributes = []
        for attribute in fixed:
            value = live(attribute.name)
            attributes.append(attribute if value is None else BundleAttribute(attribute.name, attribute.type, value))
        if transform is not None:
            attributes.append(BundleAttribute(WORLD_MATRIX, "matrixd[16]", _world_matrix(transform, world_pose)))
        if bounding_box:
            if key[0] not in self._boxes:
                self._boxes[key[0]] = _bounding_box(prim)
            attributes.extend(self._boxes[key[0]])
        return Bundle.of_prim(key[0], prim.GetTypeName(), tuple(attributes))

    def forget(self, prim_path: str) -> None:
        """Compose the prim and its descendants again on their next read (an animation moved them)."""
        below = prim_path + "/"
        for key in [key for key in self._composed if key[0] == prim_path or key[0].startswith(below)]:
            del self._composed[key]
        for path in [path for path in self._boxes if path == prim_path or path.startswith(below)]:
            del self._boxes[path]


def _composed(prim, time: float | None) -> tuple:
    """(USD's attributes with their values, (USD's world matrix, its rigid part's inverse) or None)."""
    from pxr import Gf, Usd, UsdGeom

    when = Usd.TimeCode.Default() if time is None else Usd.TimeCode(time)
    attributes = []
    for attribute in prim.GetAttributes():
        type_name = graphflow_type(str(attribute.GetTypeName()))
        if type_name is None or not attribute.HasValue():
            continue
        attributes.append(BundleAttribute(attribute.GetName(), type_name, usd_value(attribute.Get(when), type_name)))
    transform = None
    if prim.IsA(UsdGeom.Xformable):
        matrix = UsdGeom.Xformable(prim).ComputeLocalToWorldTransform(Usd.TimeCode.Default())
        transform = (matrix, Gf.Matrix4d(matrix).RemoveScaleShear().GetInverse())
    return tuple(attributes), transform


def usd_value(value, type_name: str):
    """A USD value as graphflow holds it: tuples, quaternions (x, y, z, w), matrices flat row by row."""
    if type_name.endswith("[]"):
        element = type_name[:-2]
        return tuple(usd_value(item, element) for item in value)
    if type_name.startswith("quat"):
        imaginary = value.GetImaginary()
        return (float(imaginary[0]), float(imaginary[1]), float(imaginary[2]), float(value.GetReal()))
    if type_name.startswith("matrixd"):
        return tuple(float(c) for row in value for c in row)
    if "[" in type_name:
        kind = float if not type_name.startswith("int") else int
        return tuple(kind(c) for c in value)
    if hasattr(value, "path"):          # Sdf.AssetPath
        return str(value.path)
    if type_name in ("token", "string"):
        return str(value)
    return value


def _world_matrix(transform, world_pose: Pose | None) -> tuple[float, ...]:
    """USD's local-to-world matrix with its rigid part replaced by *world_pose* (scale and shear kept)."""
    from pxr import Gf

    matrix, rigid_inverse = transform
    if world_pose is not None:
        (x, y, z), (qx, qy, qz, qw) = world_pose
        current = Gf.Matrix4d().SetRotate(Gf.Quatd(qw, qx, qy, qz))
        current.SetTranslateOnly(Gf.Vec3d(x, y, z))
        matrix = matrix * rigid_inverse * current
    return tuple(float(c) for row in matrix for c in row)


def _bounding_box(prim) -> list[BundleAttribute]:
    from pxr import Usd, UsdGeom

    cache = UsdGeom.BBoxCache(Usd.TimeCode.Default(), [UsdGeom.Tokens.default_, UsdGeom.Tokens.render,
                                                       UsdGeom.Tokens.proxy])
    box = cache.ComputeUntransformedBound(prim)
    box_range = box.GetRange()
    low: tuple[float, ...]
    high: tuple[float, ...]
    if box_range.IsEmpty():
        low = high = (0.0, 0.0, 0.0)
    else:
        low, high = tuple(float(c) for c in box_range.GetMin()), tuple(float(c) for c in box_range.GetMax())
    matrix = tuple(float(c) for row in box.GetMatrix() for c in row)
    return [BundleAttribute("bboxMinCorner", "pointd[3]", low), BundleAttribute("bboxMaxCorner", "pointd[3]", high),
            BundleAttribute("bboxTransform", "matrixd[16]", matrix)]
