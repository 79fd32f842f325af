"""What a stage authors for other simulators, which graphflow reads nowhere: named, never silently dropped.

Converted robots carry MuJoCo and Newton authoring (MjcActuator and MjcTendon prims, ``mjc:*``,
``newton:*``), URDF leftovers (``urdf:limit:effort``), Warp's ``warpSim:*`` and PhysX tendons and
mimic joints. None of it changes the PyBullet world; ``graphflow stage`` lists it, one line a prim.
"""
from __future__ import annotations

IGNORED_NAMESPACES = {
    "mjc": "MuJoCo", "mjcf": "MuJoCo import", "newton": "Newton", "urdf": "URDF", "warpSim": "Warp",
    "physxMimicJoint": "PhysX mimic joint", "physxTendon": "PhysX tendon",
}
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
        names = [attribute.GetName() for attribute in prim.GetAuthoredAttributes()
                 if attribute.GetName().split(":", 1)[0] in IGNORED_NAMESPACES]
        if names:
            sources = sorted({IGNORED_NAMESPACES[name.split(":", 1)[0]] for name in names})
            parts.append(f"{' and '.join(sources)} attributes {', '.join(sorted(names))}")
        if parts:
            found.append((str(prim.GetPath()), "; ".join(parts) + " not simulated"))
    return found
