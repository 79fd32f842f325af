"""What a stage authors that graphflow reads nowhere: named, never silently dropped.

Converted robots carry MuJoCo and Newton authoring (MjcActuator and MjcTendon prims, ``mjc:*``,
``newton:*``), URDF leftovers (``urdf:limit:effort``), Warp's ``warpSim:*``, and PhysX settings PyBullet
has no counterpart for (tendons, mimic joints, contact offsets, CCD, velocity iterations...). None of it
changes the PyBullet world; ``graphflow stage`` lists it, one line a prim.
"""
from __future__ import annotations

IGNORED_NAMESPACES = {
    "mjc": "MuJoCo", "mjcf": "MuJoCo import", "newton": "Newton", "urdf": "URDF", "warpSim": "Warp",
    "physxMimicJoint": "PhysX mimic joint", "physxTendon": "PhysX tendon",
}
# the PhysX attributes graphflow reads or reports itself (graphflow/usd/physics_import.py); any other authored
# physx* attribute changes nothing in the PyBullet world and is listed here
PHYSX_READ = {
    "physxScene:timeStepsPerSecond", "physxScene:minPositionIterationCount", "physxScene:maxPositionIterationCount",
    "physxRigidBody:disableGravity", "physxRigidBody:linearDamping", "physxRigidBody:angularDamping",
    "physxRigidBody:solverPositionIterationCount", "physxRigidBody:sleepThreshold",
    "physxArticulation:enabledSelfCollisions", "physxArticulation:solverPositionIterationCount",
    "physxArticulation:sleepThreshold", "physxJoint:maxJointVelocity", "physxJoint:armature",
    "physxJoint:jointFriction",
}
PHYSX_REPORTED_LIMITS = ("stiffness", "damping", "restitution")   # physxLimit:<axis>:*, reported when non-zero
IGNORED_PRIM_PREFIXES = {"Mjc": "MuJoCo", "Newton": "Newton"}
IGNORED_SCHEMA_WORDS = {"Mimic": "mimic joint", "Tendon": "tendon"}


def ignored_authoring(stage) -> list[tuple[str, str]]:
    """(prim path, what is ignored there) for every prim with authoring no graphflow part reads, in path order."""
    from pxr import Usd

    found = []
    for prim in Usd.PrimRange(stage.GetPseudoRoot()):
        parts = []
        kind = prim.GetTypeName()
        for prefix, source in IGNORED_PRIM_PREFIXES.items():
            if kind.startswith(prefix):
                parts.append(f"{source} prim {kind}")
        for schema in prim.GetAppliedSchemas():
            for word, what in IGNORED_SCHEMA_WORDS.items():
                if word in schema:
                    parts.append(f"{what} ({schema})")
        names = [attribute.GetName() for attribute in prim.GetAuthoredAttributes()]
        by_source: dict[str, list[str]] = {}
        for name in names:
            owner = _source(name)
            if owner is not None:
                by_source.setdefault(owner, []).append(name)
        if by_source:
            parts.append(f"{' and '.join(sorted(by_source))} attributes "
                         + ", ".join(sorted(name for group in by_source.values() for name in group)))
        if parts:
            found.append((str(prim.GetPath()), "; ".join(parts) + " not simulated"))
    return found


def _source(name: str) -> str | None:
    """Which simulator an attribute nothing here reads belongs to, or None for one graphflow reads."""
    namespace = name.split(":", 1)[0]
    if namespace in IGNORED_NAMESPACES:
        return IGNORED_NAMESPACES[namespace]
    if not namespace.startswith("physx") or name in PHYSX_READ:
        return None
    if namespace == "physxLimit" and name.rsplit(":", 1)[-1] in PHYSX_REPORTED_LIMITS:
        return None
    return "PhysX"
