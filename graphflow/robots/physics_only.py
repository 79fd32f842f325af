"""Physics-only flattening: one layer holding what the simulation reads, the visual meshes left behind.

A converted arm's visual meshes, materials and textures are megabytes graphflow never reads. The
composed stage is flattened (references, payloads and sublayers resolved into one layer) and then
loses: geometry without ``PhysicsCollisionAPI``; render materials and shaders (physics materials
stay); render material bindings; a collision mesh's normals and primvars (UVs, colours); prims
left empty that only carried notes (the URDF converter's ``urdf:name`` material scopes). Bodies,
joints, masses, colliders and drives are unchanged, so the simulation is too.
"""
from __future__ import annotations

from dataclasses import dataclass

RENDER_TYPES = ("Material", "Shader", "NodeGraph")
VISUAL_ONLY_PROPERTIES = ("normals",)


@dataclass(frozen=True)
class Flattened:
    text: str                  # the single layer, .usda text
    visual_prims: int          # geometry without a collider, dropped
    render_prims: int          # materials, shaders, node graphs dropped
    note_prims: int            # empty prims that held only notes, dropped


def flatten_physics_only(stage) -> Flattened:
    """The stage flattened to one layer, without what only rendering uses."""
    from pxr import Usd

    layer = stage.Flatten()
    layer.documentation = stage.GetRootLayer().documentation
    flat = Usd.Stage.Open(layer)
    visual, render = [], []
    for prim in flat.TraverseAll():
        if _is_visual_geometry(prim):
            visual.append(prim.GetPath())
        elif prim.GetTypeName() in RENDER_TYPES and not _has_schema(prim, "PhysicsMaterialAPI"):
            render.append(prim.GetPath())
    for path in visual + render:
        _remove(layer, path)
    for prim in flat.TraverseAll():
        spec = layer.GetPrimAtPath(prim.GetPath())
        for name in [p.name for p in spec.properties]:
            if name == "material:binding" or name.startswith("primvars:") or name in VISUAL_ONLY_PROPERTIES:
                spec.RemoveProperty(spec.properties[name])
    notes = _remove_empty_notes(flat, layer)
    return Flattened(layer.ExportToString(), len(visual), len(render), notes)


def _is_visual_geometry(prim) -> bool:
    """Geometry nothing physical is on or below: no collider, body, joint or gripper prim in its subtree."""
    from pxr import Usd, UsdGeom

    return prim.IsA(UsdGeom.Gprim) and not any(_physical(p) for p in Usd.PrimRange(prim, Usd.PrimAllPrimsPredicate))


def _physical(prim) -> bool:
    listop = prim.GetMetadata("apiSchemas")
    schemas = listop.ApplyOperations([]) if listop else []
    return (any(name.startswith(("Physics", "Physx", "Isaac")) for name in schemas)
            or prim.GetTypeName().startswith(("Physics", "Isaac")))


def _has_schema(prim, name: str) -> bool:
    listop = prim.GetMetadata("apiSchemas")
    return bool(listop) and name in listop.ApplyOperations([])


def _remove(layer, path) -> None:
    spec = layer.GetPrimAtPath(path)
    if spec is not None:
        parent = spec.nameParent or layer.pseudoRoot
        del parent.nameChildren[spec.name]


def _remove_empty_notes(flat, layer) -> int:
    """Remove, deepest first, typeless or Scope prims with no children, no schemas and only custom properties."""
    removed = 0
    for prim in sorted(flat.TraverseAll(), key=lambda p: -p.GetPath().pathElementCount):
        spec = layer.GetPrimAtPath(prim.GetPath())
        if spec is None or prim.GetTypeName() not in ("", "Scope") or spec.nameChildren:
            continue
        if prim.GetMetadata("apiSchemas") or not all(p.custom for p in spec.properties):
            continue
        if prim.GetPath() == flat.GetDefaultPrim().GetPath():
            continue
        _remove(layer, prim.GetPath())
        removed += 1
    return removed
