"""What a converted robot carries that graphflow does not simulate, one line each: never silent.

Tendons, mimic couplings, equality constraints (MuJoCo's, and the Newton mimic API the URDF
converter writes for ``<mimic>``): the joints involved move independently, each on its own drive.
Actuators that are not position servos are listed by ``drives.read_actuators``; sensors and unused
keyframes of an MJCF file by ``sources.read_mjcf``.
"""
from __future__ import annotations


def dropped_lines(stage) -> list[str]:
    """One line per tendon, mimic joint and equality constraint on *stage*, in prim order."""
    lines = []
    for prim in stage.Traverse():
        path = prim.GetPath()
        kind = prim.GetTypeName()
        schemas = authored_schemas(prim)
        if kind == "MjcTendon":
            lines.append(f"tendon {path}: dropped (its joints move independently)")
        elif kind.startswith("MjcEquality"):
            lines.append(f"equality constraint {path} ({kind}): dropped")
        if "NewtonMimicAPI" in schemas:
            leader = prim.GetRelationship("newton:mimicJoint").GetTargets()
            follows = f"follows {leader[0].name}" if leader else "follows no joint"
            lines.append(f"mimic joint {path} ({follows}): coupling dropped, driven on its own")
        for schema in schemas:
            if schema.startswith("MjcEquality"):
                lines.append(f"equality constraint on {path} ({schema}): dropped, the joint moves on its own")
    return lines


def authored_schemas(prim) -> list[str]:
    """The API schema names applied to *prim*, including those usd-core has no definition of (Newton's,
    MuJoCo's), which ``GetAppliedSchemas`` leaves out."""
    listop = prim.GetMetadata("apiSchemas")
    return list(listop.ApplyOperations([])) if listop else []
