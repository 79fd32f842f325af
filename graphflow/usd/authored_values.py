"""Authored physics values no simulation can take, found before anything is built: each named with its prim,
attribute and value on one line (PyBullet turned them into a SystemError or a pose that is not finite after
the first step: a joint frame with NaN in a text layer diverged a four-wheel robot at step 1)."""
from __future__ import annotations

import math

JOINT_FRAME = ("physics:localPos0", "physics:localPos1", "physics:localRot0", "physics:localRot1")
DRIVE_VALUES = ("stiffness", "damping", "targetPosition", "targetVelocity", "maxForce")
INERTIA_ROUNDING = 0.01     # a largest principal moment up to 1 % over the sum of the other two is rounding


def _shown(value) -> str:
    if hasattr(value, "GetReal"):          # a quaternion: (w, x, y, z) as USD writes it
        value = (value.GetReal(), *value.GetImaginary())
    if hasattr(value, "__len__"):
        return "(" + ", ".join(f"{float(v):g}" for v in value) + ")"
    return f"{float(value):g}"


def _components(value) -> list[float]:
    if hasattr(value, "GetReal"):
        return [value.GetReal(), *value.GetImaginary()]
    return [float(v) for v in value] if hasattr(value, "__len__") else [float(value)]


def mass_problems(prim, where: str) -> list[str]:
    """A MassAPI's inertia with a moment <= 0 or not finite, and a centre of mass with NaN or +infinity
    (all -infinity is USD's "not authored")."""
    problems = []
    inertia = _authored(prim, "physics:diagonalInertia")
    if inertia is not None and tuple(inertia) != (0.0, 0.0, 0.0) and not all(
            math.isfinite(value) and value > 0 for value in inertia):   # (0, 0, 0): from the colliders
        problems.append(f"{where}: physics:diagonalInertia is {_shown(inertia)}; an inertia is three finite "
                        "moments > 0, or (0, 0, 0) to compute it")
    density = _authored(prim, "physics:density")
    if density is not None and not (math.isfinite(density) and density >= 0):
        problems.append(f"{where}: physics:density is {_shown(density)}; a density must be a finite number >= 0")
    centre = _authored(prim, "physics:centerOfMass")
    if centre is not None and not (all(math.isfinite(c) for c in centre) or all(c == -math.inf for c in centre)):
        problems.append(f"{where}: physics:centerOfMass is {_shown(centre)}; a centre of mass must be finite")
    return problems


def inertia_on_triangle(diagonal: tuple) -> tuple[tuple, str | None, str | None]:
    """(moments, why they are refused or None, how they were rounded or None): each principal moment must be
    at most the sum of the other two (the triangle inequality every rigid body meets; PyBullet's inverse
    dynamics checks it strictly). Within INERTIA_ROUNDING (a thin disc or rod rounded in a converted URDF)
    the largest is lowered onto the bound; beyond, the moments are refused."""
    largest = max(range(3), key=lambda axis: diagonal[axis])
    others = sum(diagonal) - diagonal[largest]
    if diagonal[largest] <= others:
        return diagonal, None, None
    moments = "(" + ", ".join(f"{value:g}" for value in diagonal) + ") kg m^2"
    if diagonal[largest] - others > INERTIA_ROUNDING * diagonal[largest]:
        return diagonal, (f"principal moments of inertia {moments} break the triangle inequality "
                          f"({'xyz'[largest]} exceeds the sum of the other two): no rigid body has them"), None
    rounded = tuple(others if axis == largest else diagonal[axis] for axis in range(3))
    return rounded, None, (f"principal moments of inertia {moments} rounded onto the triangle inequality "
                           "(the largest lowered to the sum of the other two)")


def round_collider_problems(prim, where: str) -> list[str]:
    """A cylinder, capsule or cone collider whose radius is not > 0 or whose height is negative or not finite
    (PyBullet's createCollisionShapeArray failed with a bare "error")."""
    from pxr import UsdGeom

    for schema, kind in ((UsdGeom.Cylinder, "cylinder"), (UsdGeom.Capsule, "capsule"), (UsdGeom.Cone, "cone")):
        if prim.IsA(schema):
            radius, height = schema(prim).GetRadiusAttr().Get(), schema(prim).GetHeightAttr().Get()
            if radius is None or height is None or not (math.isfinite(radius) and radius > 0
                                                        and math.isfinite(height) and height >= 0):
                return [f"{where}: a collider {kind} of invalid size (radius {radius!r}, height {height!r})"]
    return []


def joint_problems(prim, where: str) -> list[str]:
    """A joint frame, drive value or limit with NaN (or a frame with infinity): ±infinity limits mean none."""
    problems = []
    for name in JOINT_FRAME:
        value = _authored(prim, name)
        if value is not None and not all(math.isfinite(c) for c in _components(value)):
            problems.append(f"{where}: {name} is {_shown(value)}; a joint frame must be finite")
    for attribute in prim.GetAuthoredAttributes():
        name = attribute.GetName()
        parts = name.split(":")
        checked = ((parts[0] == "drive" and parts[-1] in DRIVE_VALUES)
                   or (parts[0] == "limit" and parts[-1] in ("low", "high"))
                   or name in ("physics:lowerLimit", "physics:upperLimit"))
        value = attribute.Get() if checked else None
        if isinstance(value, float) and math.isnan(value):
            problems.append(f"{where}: {name} is nan; it must be a number")
    return problems


def _authored(prim, name: str):
    attribute = prim.GetAttribute(name)
    return attribute.Get() if attribute and attribute.HasAuthoredValue() else None


def unit_mismatches(stage) -> list[tuple[str, str]]:
    """(layer, reason) for every layer that authors metersPerUnit other than the stage's: USD composes its
    values unscaled (a wheel authored in centimetres became 100x larger and flung its robot 95 m)."""
    from pxr import UsdGeom

    stage_units = UsdGeom.GetStageMetersPerUnit(stage)
    found = []
    for layer in stage.GetLayerStack(includeSessionLayers=False)[1:] + _referenced_layers(stage):
        root = layer.pseudoRoot
        if root.HasInfo("metersPerUnit") and not math.isclose(root.GetInfo("metersPerUnit"), stage_units):
            found.append((layer.identifier, f"layer authored in metersPerUnit {root.GetInfo('metersPerUnit'):g}, "
                          f"composed unscaled into a stage of {stage_units:g}: its lengths are read as the stage's"))
    return sorted(set(found))


def _referenced_layers(stage) -> list:
    stack = set(stage.GetLayerStack(includeSessionLayers=True))
    return [layer for layer in stage.GetUsedLayers() if layer not in stack]
