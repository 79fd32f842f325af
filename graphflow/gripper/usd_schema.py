"""Isaac Sim's surface-gripper USD schema, registered with usd-core as a codeless plugin.

The plugin (``schema/plugInfo.json`` + ``schema/generatedSchema.usda``) declares
``IsaacSurfaceGripper`` and the single-apply ``IsaacAttachmentPointAPI`` with
Isaac's exact attribute names, so ``prim.IsA`` / ``prim.HasAPI`` work and
unauthored attributes read their fallbacks.

Fallback choice (reference §1.1): Isaac declares the type ``abstractTyped``, so
USD supplies no fallbacks and its C++ runtime keeps its own defaults (notably
``maxGripDistance`` 0.0, a 1 mm ray). We declare it ``concreteTyped`` so the
documented schema fallbacks apply (``maxGripDistance`` 0.01, limits -1,
``retryInterval`` 0, ``status`` Open). Only files that leave
``maxGripDistance`` unauthored behave differently; Isaac's own files and tests
always author it.
"""
from __future__ import annotations

import os
import threading

SURFACE_GRIPPER_TYPE = "IsaacSurfaceGripper"
ATTACHMENT_POINT_API = "IsaacAttachmentPointAPI"

ATTACHMENT_POINTS = "isaac:attachmentPoints"
GRIPPED_OBJECTS = "isaac:grippedObjects"
MAX_GRIP_DISTANCE = "isaac:maxGripDistance"
RETRY_INTERVAL = "isaac:retryInterval"
SHEAR_FORCE_LIMIT = "isaac:shearForceLimit"
COAXIAL_FORCE_LIMIT = "isaac:coaxialForceLimit"
STATUS = "isaac:status"
FORWARD_AXIS = "isaac:forwardAxis"
CLEARANCE_OFFSET = "isaac:clearanceOffset"

SCHEMA_DIRECTORY = os.path.join(os.path.dirname(os.path.abspath(__file__)), "schema")

_registered = False
_lock = threading.Lock()


def register_schema() -> None:
    """Register the codeless schema plugin once per process (before the first stage that uses it)."""
    global _registered
    with _lock:
        if _registered:
            return
        from pxr import Plug

        Plug.Registry().RegisterPlugins(SCHEMA_DIRECTORY)
        _registered = True


def _sdf_types():
    from pxr import Sdf

    return {
        STATUS: Sdf.ValueTypeNames.Token,
        SHEAR_FORCE_LIMIT: Sdf.ValueTypeNames.Float,
        COAXIAL_FORCE_LIMIT: Sdf.ValueTypeNames.Float,
        MAX_GRIP_DISTANCE: Sdf.ValueTypeNames.Float,
        RETRY_INTERVAL: Sdf.ValueTypeNames.Float,
    }


def define_surface_gripper(stage, prim_path: str):
    """Define an ``IsaacSurfaceGripper`` at *prim_path* as Isaac's ``robot_schema.CreateSurfaceGripper``.

    The five attributes and two relationships are created (non-custom) with no
    authored value, so they read the schema fallbacks until set.
    """
    register_schema()
    prim = stage.DefinePrim(prim_path, SURFACE_GRIPPER_TYPE)
    for name, value_type in _sdf_types().items():
        prim.CreateAttribute(name, value_type, False)
    prim.CreateRelationship(ATTACHMENT_POINTS, False)
    prim.CreateRelationship(GRIPPED_OBJECTS, False)
    return prim


def next_free_path(stage, path: str) -> str:
    """``path`` if unused, else ``path_01``, ``path_02``, ... (as ``omni.usd.get_stage_next_free_path``)."""
    if not stage.GetPrimAtPath(path):
        return path
    index = 1
    while stage.GetPrimAtPath(f"{path}_{index:02d}"):
        index += 1
    return f"{path}_{index:02d}"


def create_surface_gripper(stage, parent_path: str):
    """Create a surface gripper under *parent_path*, named ``SurfaceGripper`` or the next free ``SurfaceGripper_NN``."""
    base = parent_path.rstrip("/") + "/SurfaceGripper"
    return define_surface_gripper(stage, next_free_path(stage, base))


def apply_attachment_point_api(joint_prim, forward_axis: str | None = None, clearance_offset: float | None = None) -> None:
    """Apply ``IsaacAttachmentPointAPI`` to a joint prim; author the two attributes only when given."""
    register_schema()
    from pxr import Sdf

    if not joint_prim.HasAPI(ATTACHMENT_POINT_API):
        joint_prim.AddAppliedSchema(ATTACHMENT_POINT_API)
    if forward_axis is not None:
        joint_prim.CreateAttribute(FORWARD_AXIS, Sdf.ValueTypeNames.Token, False).Set(forward_axis)
    if clearance_offset is not None:
        joint_prim.CreateAttribute(CLEARANCE_OFFSET, Sdf.ValueTypeNames.Float, False).Set(float(clearance_offset))


def is_surface_gripper(prim) -> bool:
    """True for a prim whose type name is exactly ``IsaacSurfaceGripper`` (Isaac's runtime test)."""
    return bool(prim) and prim.GetTypeName() == SURFACE_GRIPPER_TYPE


def find_surface_grippers(stage) -> list[str]:
    """Paths of every ``IsaacSurfaceGripper`` prim on the stage, in traversal order."""
    from pxr import Usd

    return [prim.GetPath().pathString for prim in stage.Traverse(Usd.TraverseInstanceProxies())
            if is_surface_gripper(prim)]


def read_float(prim, name: str, default: float) -> float:
    """An attribute's value (authored or fallback), else *default* when it has none."""
    attribute = prim.GetAttribute(name)
    value = attribute.Get() if attribute else None
    return float(value) if value is not None else default


def read_forward_axis(joint_prim) -> str:
    """``X``, ``Y`` or ``Z`` from the first character of ``isaac:forwardAxis``; anything else is X (as Isaac)."""
    attribute = joint_prim.GetAttribute(FORWARD_AXIS)
    value = attribute.Get() if attribute else None
    first = str(value)[:1].upper() if value else ""
    return first if first in ("Y", "Z") else "X"


def set_gripper_properties(prim, *, max_grip_distance=None, coaxial_force_limit=None,
                           shear_force_limit=None, retry_interval=None) -> None:
    """Author the given properties (None leaves one unchanged)."""
    from pxr import Sdf

    for name, value in ((MAX_GRIP_DISTANCE, max_grip_distance), (COAXIAL_FORCE_LIMIT, coaxial_force_limit),
                        (SHEAR_FORCE_LIMIT, shear_force_limit), (RETRY_INTERVAL, retry_interval)):
        if value is not None:
            prim.CreateAttribute(name, Sdf.ValueTypeNames.Float, False).Set(float(value))
