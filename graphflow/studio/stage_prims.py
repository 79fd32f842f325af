"""The prims of a graph's stage with their kinds, for the studio's target pickers.

A ``target`` input must name a prim of the kind its node works on (a surface gripper, an
articulation, a rigid body: ``graphflow.validate.stage_names.PRIM_KINDS``); the picker offers the
stage's prims of that kind. The stage is read with the same usd-core code a run uses, and only
from the served folder or graphflow's packaged assets: a graph naming a stage elsewhere gets a
clear refusal, not a listing of someone's disk.
"""
from __future__ import annotations

import warnings
from pathlib import Path

from graphflow.errors import BadInput
from graphflow.validate.stage_names import ANY_PRIM, ARTICULATION, PRIM_KINDS, RIGID_BODY, SURFACE_GRIPPER

JOINT, XFORM, COLLIDER = "joint", "xform", "static collider"
CHECK_FIELD_KINDS = {"prim": ANY_PRIM, "object": ANY_PRIM, "prims": ANY_PRIM, "gripper": SURFACE_GRIPPER}   # as validate


def port_kind(spec_id: str, attribute) -> str | None:
    """The kind of prim an input names (None: it names no prim)."""
    kind = PRIM_KINDS.get((spec_id, attribute.name))
    if kind is None and attribute.type in ("target", "path"):
        return ANY_PRIM
    return kind


def _stage_file(reference: str, graph: Path, root: Path) -> Path:
    from graphflow.usd.errors import StageError
    from graphflow.usd.resolver import ASSET_DIRECTORY, resolve_stage

    try:
        found = resolve_stage(reference, graph.parent).resolve()
    except StageError as error:
        raise BadInput(f"settings.stage: {error}") from None
    if not any(found == folder or folder in found.parents for folder in (root, ASSET_DIRECTORY.resolve())):
        raise BadInput(f"settings.stage {reference!r} is outside the served folder: the studio lists only its prims")
    if not found.is_file():
        raise BadInput(f"settings.stage {reference!r}: no such stage file")
    return found


def stage_prims(reference: str, graph: Path, root: Path) -> dict:
    """Every prim of the stage *reference* names (relative to the graph file *graph*): path, USD type, kinds."""
    from pxr import UsdGeom

    from graphflow.usd.errors import StageError
    from graphflow.usd.physics_import import load_description, open_stage

    path = _stage_file(reference, graph, root)
    try:
        usd_stage, _label = open_stage(path)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")   # unsupported prims are the run's to report
            description = load_description(usd_stage)
    except StageError as error:
        raise BadInput(f"settings.stage {reference!r}: {error}") from None
    roots = {articulation.path for articulation in description.articulations}
    grippers = {gripper.path for gripper in description.surface_grippers}
    prims = []
    for prim in usd_stage.Traverse():
        name, type_name = str(prim.GetPath()), prim.GetTypeName()
        body = description.bodies.get(name)
        moves = body is not None and body.kind != "static"   # a static collider has no RigidBodyAPI
        kinds = [kind for kind, holds in ((RIGID_BODY, moves), (COLLIDER, body is not None and not moves),
                                          (ARTICULATION, name in roots),
                                          (JOINT, name in description.joints),
                                          (SURFACE_GRIPPER, name in grippers or type_name == "IsaacSurfaceGripper"),
                                          (XFORM, prim.IsA(UsdGeom.Xformable))) if holds]
        prims.append({"path": name, "type": type_name, "kinds": kinds})
    return {"stage": reference, "prims": prims}


STAGE_SUFFIXES = (".usd", ".usda", ".usdc")


def stage_choices(graph: Path, root: Path, limit: int = 500) -> list[str]:
    """What ``settings.stage`` may name, for the settings editor: packaged assets, then stage files under the folder.

    Files are given relative to the graph's own folder, as ``settings.stage`` takes them.
    """
    import os

    from graphflow.usd.resolver import ASSET_DIRECTORY

    choices = [f"asset:{path.name}" for path in sorted(ASSET_DIRECTORY.iterdir()) if path.suffix in STAGE_SUFFIXES]
    for path in sorted(root.rglob("*")):
        parts = path.relative_to(root).parts
        if path.suffix in STAGE_SUFFIXES and not any(part.startswith(".") for part in parts) and path.is_file():
            resolved = path.resolve()
            if resolved == root or root in resolved.parents:   # no symbolic link out of the folder
                choices.append(Path(os.path.relpath(path, graph.parent)).as_posix())
        if len(choices) >= limit:
            break
    return choices
