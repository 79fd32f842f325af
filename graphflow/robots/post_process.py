"""graphflow's post-processing of a converted robot, on usd-core alone: articulation root on the robot
prim, home pose, drives, an optional suction tool, the list of what is dropped, optional flattening.

The result is one of two shapes. Physics-only: a single flattened .usda, visual geometry left
behind. Otherwise: a small .usda whose sublayer is the converter's own output (copied next to it)
and which overrides it with graphflow's additions, so the visuals stay and nothing is rewritten.
"""
from __future__ import annotations

import math
import warnings
from dataclasses import dataclass, field
from pathlib import Path

from graphflow.robots.drives import author_drives, plan_gains, read_actuators
from graphflow.robots.dropped import dropped_lines
from graphflow.robots.gains import Gains
from graphflow.robots.home import author_home, choose_home, movable_joints
from graphflow.robots.physics_only import flatten_physics_only
from graphflow.robots.sources import MjcfFacts
from graphflow.robots.suction import add_suction_tool


@dataclass
class Options:
    home: dict[str, float] = field(default_factory=dict)       # by joint name, rad or m
    physics_only: bool = False
    suction_link: str | None = None                             # a link (body) name: add a suction tool there
    suction_tip: float = 0.1                                    # m along the link's +Z
    provenance: str = ""                                        # the layer's doc: how it was made


@dataclass
class Outcome:
    text: str | None                  # the flattened layer (physics-only), else None: the stage was saved
    lines: list[str]                  # the report, one fact a line
    gains: dict[str, Gains]           # by joint path
    home: dict[str, float]            # by joint path
    dropped: list[str]
    gripper: str | None = None


def post_process(stage, options: Options, mjcf: MjcfFacts | None = None) -> Outcome:
    """Apply graphflow's additions to *stage* (edits go to its edit target); see the module docstring."""
    from graphflow.usd.errors import UnsupportedPrimWarning
    from graphflow.usd.physics_import import load_description

    lines = _root_on_robot(stage)
    mjcf = mjcf or MjcfFacts()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", UnsupportedPrimWarning)
        authored = load_description(stage)
        home, sources = choose_home(authored, options.home, mjcf.keyframe)
        author_home(stage, authored, home)
        posed = load_description(stage)                 # the inertia each joint carries is taken at home
    joints = movable_joints(posed)
    servos, unmapped = read_actuators(stage)
    gains = plan_gains(stage, posed, joints, servos, mjcf.damping)
    author_drives(stage, joints, gains, home)
    for joint in joints:
        lines.append(_drive_line(joint, gains[joint.path], home[joint.path], sources[joint.path], mjcf))
    if not joints:
        lines.append("no movable joints: nothing to drive")
    gripper = None
    if options.suction_link:
        gripper = add_suction_tool(stage, _link_path(posed, options.suction_link), options.suction_tip)
        lines.append(f"suction tool: {gripper}, tip {options.suction_tip:g} m along {options.suction_link} +Z")
    dropped = dropped_lines(stage) + unmapped + mjcf.lost
    lines += [f"dropped: {line}" for line in dropped] or ["dropped: nothing (no tendons, mimic joints, "
                                                          "equality constraints, unmapped actuators or sensors)"]
    text = None
    if options.provenance:
        stage.GetEditTarget().GetLayer().documentation = options.provenance
    if options.physics_only:
        flat = flatten_physics_only(stage)
        text = flat.text
        lines.append(f"physics-only: dropped {flat.visual_prims} visual-only geometry prims, {flat.render_prims} "
                     f"materials and shaders, {flat.note_prims} note prims; textures not copied")
    return Outcome(text, lines, gains, home, dropped, gripper)


def _root_on_robot(stage) -> list[str]:
    """Move the articulation root from a link to the robot's default prim (as Isaac's assets have it), so a
    graph names the robot (``/World/panda``), not its base link."""
    from pxr import UsdPhysics

    robot = stage.GetDefaultPrim()
    if not robot or robot.HasAPI(UsdPhysics.ArticulationRootAPI) or robot.HasAPI(UsdPhysics.RigidBodyAPI):
        return []
    roots = [prim for prim in stage.Traverse() if prim.HasAPI(UsdPhysics.ArticulationRootAPI)]
    if len(roots) != 1:
        return []
    roots[0].RemoveAPI(UsdPhysics.ArticulationRootAPI)
    UsdPhysics.ArticulationRootAPI.Apply(robot)
    return [f"articulation root: moved from {roots[0].GetPath()} to {robot.GetPath()}"]


def _link_path(description, name: str) -> str:
    from graphflow.errors import BadInput

    found = [path for path in description.bodies if path.rsplit("/", 1)[-1] == name]
    if len(found) != 1:
        raise BadInput(f"--suction: no single link named {name} (links: "
                       f"{', '.join(sorted(p.rsplit('/', 1)[-1] for p in description.bodies))})")
    return found[0]


def _drive_line(joint, gains: Gains, home: float, source: str, mjcf: MjcfFacts) -> str:
    angular = joint.kind == "revolute"
    unit, per = ("N m", "rad") if angular else ("N", "m")
    limit = f"max {gains.max_force:g} {unit}" if gains.max_force is not None else "no force limit in the source"
    where = f"keyframe {mjcf.keyframe_name}" if source == "keyframe" else source
    shown = f"{math.degrees(home):.4g} deg" if angular else f"{home:.4g} m"
    return (f"drive {joint.path.rsplit('/', 1)[-1]}: k {gains.stiffness:.6g} {unit}/{per}, d {gains.damping:.6g} "
            f"{unit} s/{per} ({gains.source}), {limit}; home {shown} ({where})")


def folder_bytes(folder: Path) -> int:
    """Bytes of every file under *folder* (a converter's output: layers, meshes, textures)."""
    return sum(path.stat().st_size for path in folder.rglob("*") if path.is_file())
