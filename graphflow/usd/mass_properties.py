"""A rigid body's mass properties as USD's precedence rules give them, with PhysX's fallbacks.

MassAPI on the body first, then its colliders (each shape's volume and inertia at the density it gets),
then 1000 kg/m^3 (USD's and PhysX's default). What usd-core cannot integrate (no enabled collider) is
taken from the body's own geometry instead of usd-core's unseeded guess; a body with neither mass nor
colliders (a frame, a converted MJCF site) gets a documented small mass, named.
"""
from __future__ import annotations

import math
from typing import Any, Callable, NoReturn

from graphflow.poses import AXIS_VECTORS, Vec3, quat_normalize
from graphflow.usd.authored_values import inertia_on_triangle
from graphflow.usd.description import Body, MassProperties, Shape

FRAME_BODY_MASS = 1.0e-3               # kg
FRAME_BODY_INERTIA = 0.4 * FRAME_BODY_MASS * 0.01 ** 2    # kg m^2


def quat_of(gf_quat) -> tuple[float, float, float, float]:
    """Gf quaternion (real, i, j, k) -> graphflow (x, y, z, w)."""
    imaginary = gf_quat.GetImaginary()
    return quat_normalize((float(imaginary[0]), float(imaginary[1]), float(imaginary[2]), float(gf_quat.GetReal())))


class MassPropertiesMixin:
    """The stage importer's mass-property reading (it provides mpu, xform_cache, _vec, _fail, _unsupported)."""

    mpu: float
    xform_cache: Any                               # a pxr UsdGeom.XformCache: pxr has no type information
    _vec: Callable[..., Vec3]                      # (vector, scale=mpu) -> metres
    _fail: Callable[[str], NoReturn]
    _unsupported: Callable[[str, str], None]

    def _mass_properties(self, prim, body: Body) -> MassProperties:
        """Mass, centre of mass and inertia by USD's precedence rules (MassAPI on body, colliders, materials).

        With nothing authored, USD uses 1000 kg/m^3 (PhysX's default density too).
        """
        from pxr import Gf, UsdPhysics

        shapes = {shape.path: shape for shape in body.shapes}
        inverse_mpu = 1.0 / self.mpu

        def mass_information(collider_prim):
            info = UsdPhysics.RigidBodyAPI.MassInformation()
            shape = shapes.get(str(collider_prim.GetPath()))
            if shape is None:
                info.volume = -1.0  # not a collider we simulate: contributes nothing
                return info
            volume, inertia, center = unit_density_properties(shape)
            info.volume = volume * inverse_mpu ** 3
            info.inertia = Gf.Matrix3f(inertia[0] * inverse_mpu ** 5, 0, 0, 0, inertia[1] * inverse_mpu ** 5, 0,
                                       0, 0, inertia[2] * inverse_mpu ** 5)
            info.centerOfMass = Gf.Vec3f(*(c * inverse_mpu for c in center))
            info.localPos = Gf.Vec3f(*(c * inverse_mpu for c in shape.pose[0]))
            x, y, z, w = shape.pose[1]
            info.localRot = Gf.Quatf(w, x, y, z)
            return info

        mass, diagonal, center, axes = UsdPhysics.RigidBodyAPI(prim).ComputeMassProperties(mass_information)
        mass = float(mass)
        if not all(math.isfinite(float(c)) for c in center):
            # MassAPI's "not authored" sentinel (-inf) comes back when no collider gave a centre of mass
            # (the crab_hex plates, the Robotiq base mount): PhysX then uses the body origin
            center = (0.0, 0.0, 0.0)
        diagonal = tuple(float(c) * self.mpu ** 2 for c in diagonal)
        principal_axes = quat_of(axes)
        mass_api = UsdPhysics.MassAPI(prim)
        if prim.HasAPI(UsdPhysics.MassAPI) and mass_api.GetDiagonalInertiaAttr().HasAuthoredValue():
            # usd-core leaves the axes uninitialised when only the diagonal is authored: identity, as PhysX
            authored = mass_api.GetPrincipalAxesAttr().Get() if mass_api.GetPrincipalAxesAttr().HasAuthoredValue() else None
            has_axes = authored is not None and (authored.GetReal() != 0 or any(authored.GetImaginary()))
            principal_axes = quat_of(authored) if has_axes else (0.0, 0.0, 0.0, 1.0)
        if mass <= 0.0:
            self._unsupported(str(prim.GetPath()), "a rigid body without mass or colliders (a frame or a site): "
                              f"given {FRAME_BODY_MASS * 1000:g} g, a 1 cm sphere's inertia")
            mass, diagonal = FRAME_BODY_MASS, (FRAME_BODY_INERTIA,) * 3
            # a sphere's inertia has no preferred axes; usd-core's are uninitialised here (no collider)
            principal_axes = (0.0, 0.0, 0.0, 1.0)
        elif not any(shape.collision_enabled for shape in body.shapes) and not (
                prim.HasAPI(UsdPhysics.MassAPI) and mass_api.GetDiagonalInertiaAttr().HasAuthoredValue()):
            # usd-core found no collider to integrate: it warns "possibly invalid inertia tensor of
            # {1,1,1}", uses a small sphere's inertia and leaves the principal axes uninitialised (they
            # changed from run to run, and so did the simulation). Use the body's own geometry instead.
            diagonal, principal_axes = geometry_inertia(self._fallback_shapes(prim, body), mass,
                                                         self._vec(center), diagonal)
        diagonal, refused, rounded = inertia_on_triangle(diagonal)
        if refused:
            self._fail(f"body {prim.GetPath()}: {refused}")
        if rounded:
            self._unsupported(str(prim.GetPath()), rounded)
        return MassProperties(mass=mass, center_of_mass=self._vec(center), diagonal_inertia=diagonal,
                              principal_axes=principal_axes)

    def _fallback_shapes(self, prim, body: Body) -> list[Shape]:
        """Shapes to take a body's inertia from when it has no enabled collider: its disabled
        colliders, else its own Cube or Sphere geometry (the krabby's tibias)."""
        from pxr import Gf, UsdGeom

        if body.shapes:
            return list(body.shapes)
        scale = Gf.Transform(Gf.Matrix4d(self.xform_cache.GetLocalToWorldTransform(prim))).GetScale()
        scale = tuple(abs(float(c)) * self.mpu for c in scale)
        path, origin = str(prim.GetPath()), ((0.0, 0.0, 0.0), (0.0, 0.0, 0.0, 1.0))
        if prim.IsA(UsdGeom.Cube):
            half = 0.5 * float(UsdGeom.Cube(prim).GetSizeAttr().Get())
            return [Shape(path, "box", origin, half_extents=(half * scale[0], half * scale[1], half * scale[2]))]
        if prim.IsA(UsdGeom.Sphere) and scale[0] == scale[1] == scale[2]:
            return [Shape(path, "sphere", origin, radius=float(UsdGeom.Sphere(prim).GetRadiusAttr().Get()) * scale[0])]
        return []


def unit_density_properties(shape: Shape):
    """(volume, principal inertia for density 1, centre of mass) of a shape in its own frame, SI units."""
    if shape.kind == "box":
        a, b, c = shape.half_extents
        volume = 8.0 * a * b * c
        return volume, (volume * (b * b + c * c) / 3.0, volume * (a * a + c * c) / 3.0,
                        volume * (a * a + b * b) / 3.0), (0.0, 0.0, 0.0)
    if shape.kind == "sphere":
        r = shape.radius
        volume = 4.0 / 3.0 * math.pi * r ** 3
        return volume, (0.4 * volume * r * r,) * 3, (0.0, 0.0, 0.0)
    if shape.kind in ("cylinder", "capsule", "cone"):
        r, h = shape.radius, 2.0 * shape.half_height
        center = (0.0, 0.0, 0.0)
        if shape.kind == "cylinder":
            volume = math.pi * r * r * h
            axial, transverse = 0.5 * volume * r * r, volume * (3.0 * r * r + h * h) / 12.0
        elif shape.kind == "capsule":
            cylinder, spheres = math.pi * r * r * h, 4.0 / 3.0 * math.pi * r ** 3
            volume = cylinder + spheres
            axial = 0.5 * cylinder * r * r + 0.4 * spheres * r * r
            transverse = (cylinder * (h * h / 12.0 + r * r / 4.0)
                          + spheres * (0.4 * r * r + h * h / 4.0 + 3.0 * h * r / 8.0))
        else:
            volume = math.pi * r * r * h / 3.0
            axial, transverse = 0.3 * volume * r * r, volume * (3.0 * r * r / 20.0 + 3.0 * h * h / 80.0)
            x, y, z = AXIS_VECTORS[shape.axis]
            center = (-0.25 * h * x, -0.25 * h * y, -0.25 * h * z)
        inertia = tuple(axial if c else transverse for c in AXIS_VECTORS[shape.axis])
        return volume, inertia, center
    # meshes: their bounding box
    xs, ys, zs = zip(*shape.points)
    half = (0.5 * (max(xs) - min(xs)), 0.5 * (max(ys) - min(ys)), 0.5 * (max(zs) - min(zs)))
    center = (0.5 * (max(xs) + min(xs)), 0.5 * (max(ys) + min(ys)), 0.5 * (max(zs) + min(zs)))
    volume = 8.0 * half[0] * half[1] * half[2]
    return volume, (volume * (half[1] ** 2 + half[2] ** 2) / 3.0, volume * (half[0] ** 2 + half[2] ** 2) / 3.0,
                    volume * (half[0] ** 2 + half[1] ** 2) / 3.0), center


def geometry_inertia(shapes: list[Shape], mass: float, center_of_mass, fallback_diagonal):
    """(principal inertia, principal axes as xyzw) of *mass* spread evenly over *shapes* (body frame),
    about *center_of_mass*; a small sphere's inertia on identity axes when there are no shapes."""
    import numpy as np
    from pxr import Gf

    parts = [(shape, *unit_density_properties(shape)) for shape in shapes]
    total = sum(volume for _shape, volume, _inertia, _center in parts)
    if not total > 0.0:
        return tuple(fallback_diagonal), (0.0, 0.0, 0.0, 1.0)
    tensor = np.zeros((3, 3))
    for shape, volume, inertia, center in parts:
        share = mass * volume / total
        rotation = np.array(Gf.Matrix3d(Gf.Rotation(Gf.Quatd(shape.pose[1][3], *shape.pose[1][:3]))).GetTranspose())
        offset = np.array(shape.pose[0]) + rotation @ np.array(center) - np.array(center_of_mass)
        tensor += rotation @ np.diag(np.array(inertia) * share / volume) @ rotation.T
        tensor += share * (offset @ offset * np.eye(3) - np.outer(offset, offset))
    values, vectors = np.linalg.eigh(tensor)
    if np.linalg.det(vectors) < 0:
        vectors[:, 2] = -vectors[:, 2]
    quat = Gf.Matrix3d(*vectors.T.flatten().tolist()).ExtractRotation().GetQuat()
    return tuple(float(v) for v in values), quat_of(quat)
