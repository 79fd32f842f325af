"""What the converters leave out of the USD but graphflow needs, read from the MJCF source itself.

``mujoco-usd-converter`` 0.8 drops keyframes and sensors ("not supported") and writes a joint's
damping in per-degree units; the source file still has them. A URDF's effort limits, mimic joints
and safety controllers do reach the USD (``urdf:limit:effort``, ``NewtonMimicAPI``), so a URDF
needs nothing from here.
"""
from __future__ import annotations

import xml.etree.ElementTree as ElementTree
from dataclasses import dataclass, field
from pathlib import Path

from graphflow.errors import BadInput

QPOS_WIDTH = {"hinge": 1, "slide": 1, "ball": 4, "free": 7}


@dataclass
class MjcfFacts:
    """Joint damping (SI, per radian or metre), the home keyframe (by joint name), what the USD lost."""

    damping: dict[str, float] = field(default_factory=dict)
    keyframe: dict[str, float] = field(default_factory=dict)
    keyframe_name: str | None = None
    lost: list[str] = field(default_factory=list)       # one line each: sensors, keyframes not used


def read_mjcf(path: Path) -> MjcfFacts:
    """The facts above from an MJCF file; a file that is not XML is a BadInput naming it."""
    try:
        root = ElementTree.parse(path).getroot()
    except (ElementTree.ParseError, OSError) as error:
        raise BadInput(f"{path}: not a readable MJCF file ({error})") from None
    facts = MjcfFacts()
    joints = []     # (name, type) in qpos order: MuJoCo numbers DOFs in the document order of the bodies
    for joint in root.iter():
        if joint.tag == "freejoint":
            joints.append((joint.get("name", ""), "free"))
        elif joint.tag == "joint" and _in_worldbody(root, joint):
            joints.append((joint.get("name", ""), joint.get("type", "hinge")))
            damping = joint.get("damping")
            if damping:
                facts.damping[joint.get("name", "")] = float(damping)
    keys = root.findall("./keyframe/key")
    chosen = next((key for key in keys if key.get("name") == "home"), keys[0] if keys else None)
    if chosen is not None:
        facts.keyframe_name = chosen.get("name") or "the first keyframe"
        facts.keyframe = _qpos_by_joint(joints, chosen.get("qpos", ""))
    for key in keys:
        if key is not chosen:
            facts.lost.append(f"keyframe {key.get('name') or '(unnamed)'}: dropped (only the home pose is kept)")
    for sensors in root.findall("./sensor"):
        for sensor in sensors:
            facts.lost.append(f"sensor {sensor.get('name') or '(unnamed)'} ({sensor.tag}): dropped (graphflow reads "
                              "joint and body state through its own nodes)")
    return facts


def _in_worldbody(root, element) -> bool:
    return any(element in body.iter() for body in root.findall("./worldbody"))


def _qpos_by_joint(joints, qpos_text: str) -> dict[str, float]:
    """The one-value joints' keyframe values by name (ball and free joints take 4 and 7 values and are skipped)."""
    values = [float(v) for v in qpos_text.split()]
    by_name, index = {}, 0
    for name, kind in joints:
        width = QPOS_WIDTH.get(kind, 1)
        if width == 1 and index < len(values):
            by_name[name] = values[index]
        index += width
    return by_name
