"""Transforms that animation nodes write on prims physics does not simulate, kept off the stage's files.

The maneuver nodes (TranslateToLocation, MoveToTarget, ...) move a plain Xform
or a visual prim by writing its xform ops. ``AnimationLayer`` authors them on an
anonymous sub-layer of the stage's session layer: reads of the composed stage
(ReadPrimAttribute, read_prim, world poses) see them, the files on disk never
do, and ``clear()`` (the world's reset) returns every prim to the file's value.
Values here are in stage units; the world converts to and from metres.
"""
from __future__ import annotations

from graphflow.world import WorldError

LAYER_TAG = "anon_graphflow_animation_"
OP_ORDER = ("xformOp:translate", "xformOp:orient", "xformOp:scale")
_VECTORS = {"float3": "Vec3f", "double3": "Vec3d", "half3": "Vec3h"}
_QUATERNIONS = {"quatf": ("Quatf", "Vec3f"), "quatd": ("Quatd", "Vec3d"), "quath": ("Quath", "Vec3h")}


class AnimationLayer:
    """The session sub-layer holding animated xform ops of one stage (created on the first write)."""

    def __init__(self, stage):
        self.stage = stage
        self._layer = None
        self._written: set[str] = set()      # prims with animated ops since the last clear

    def local_transform(self, prim_path: str):
        """(translation, orientation (x, y, z, w), scale) of the prim in its parent's frame, stage units."""
        from pxr import Gf, UsdGeom

        prim = self._xformable(prim_path)
        transform = Gf.Transform(UsdGeom.Xformable(prim).GetLocalTransformation())
        quaternion = transform.GetRotation().GetQuat()
        imaginary = quaternion.GetImaginary()
        return (tuple(float(c) for c in transform.GetTranslation()),
                (float(imaginary[0]), float(imaginary[1]), float(imaginary[2]), float(quaternion.GetReal())),
                tuple(float(c) for c in transform.GetScale()))

    def write(self, prim_path: str, translation, orientation, scale) -> None:
        """Author translate, orient and scale ops (in that order) on the animation layer."""
        from pxr import Gf, Sdf, Usd, UsdGeom

        prim = self._xformable(prim_path)
        self._written.add(prim_path)
        session = self.stage.GetSessionLayer()
        for name in OP_ORDER + ("xformOpOrder",):
            if session.GetPropertyAtPath(Sdf.Path(prim_path).AppendProperty(name)):
                raise WorldError(f"{prim_path}: {name} is set on the stage's session layer (a sweep or variant "
                                 "override), which an animation cannot override")
        with Usd.EditContext(self.stage, self._edit_layer()):
            values = (translation, orientation, scale)
            for name, value, default_type in zip(OP_ORDER, values, ("double3", "quatd", "double3")):
                attribute = prim.GetAttribute(name)
                if not attribute:
                    attribute = prim.CreateAttribute(name, getattr(Sdf.ValueTypeNames, default_type.capitalize()))
                attribute.Set(_usd_value(Gf, str(attribute.GetTypeName()), value, prim_path, name))
            xformable = UsdGeom.Xformable(prim)
            order = list(OP_ORDER)
            if xformable.GetResetXformStack():
                order.insert(0, "!resetXformStack!")
            xformable.GetXformOpOrderAttr().Set(order)

    def clear(self) -> list[str]:
        """Forget every animated transform (the world's reset); the prims that had one."""
        if self._layer is not None:
            self._layer.Clear()
        written, self._written = sorted(self._written), set()
        return written

    def close(self) -> None:
        """Take the layer off the stage: a later world on the same stage starts from the file's values."""
        if self._layer is not None:
            self._layer.Clear()
            sublayers = self.stage.GetSessionLayer().subLayerPaths
            if self._layer.identifier in sublayers:
                sublayers.remove(self._layer.identifier)
            self._layer = None

    def _edit_layer(self):
        from pxr import Sdf

        if self._layer is None:
            self._layer = Sdf.Layer.CreateAnonymous(LAYER_TAG)
            self.stage.GetSessionLayer().subLayerPaths.insert(0, self._layer.identifier)
        return self._layer

    def _xformable(self, prim_path: str):
        from pxr import UsdGeom

        prim = self.stage.GetPrimAtPath(prim_path) if self.stage is not None and prim_path.startswith("/") else None
        if not prim:
            raise WorldError(f"no prim {prim_path} on this stage")
        if not prim.IsA(UsdGeom.Xformable):
            raise WorldError(f"{prim_path} is a {prim.GetTypeName() or 'typeless prim'}, which has no transform")
        return prim


def _usd_value(Gf, type_name: str, value, prim_path: str, name: str):
    if type_name in _VECTORS:
        return getattr(Gf, _VECTORS[type_name])(*(float(c) for c in value))
    if type_name in _QUATERNIONS:
        quaternion, vector = _QUATERNIONS[type_name]
        x, y, z, w = (float(c) for c in value)
        return getattr(Gf, quaternion)(w, getattr(Gf, vector)(x, y, z))
    raise WorldError(f"{prim_path}: {name} is authored as {type_name}, not a 3-vector or quaternion")
