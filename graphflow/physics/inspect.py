"""``graphflow stage STAGE.usda [--json] [--simulate SECONDS]``: what a stage holds, and whether it rests.

The CLI calls ``run_stage_command``; it prints to stdout, reports a bad stage
as one line on stderr and returns the exit code (0 ok, 1 the simulation diverged, 2 bad input).
"""
from __future__ import annotations

import json
import math
import sys
import warnings

from graphflow.usd.description import StageDescription
from graphflow.usd.errors import StageError, UnsupportedPrimWarning

EXIT_OK = 0
EXIT_RUNTIME = 1
EXIT_BAD_INPUT = 2


def stage_report(description: StageDescription) -> dict:
    """The stage summary as a JSON-ready dict."""
    bodies = description.bodies
    joints_by_kind: dict[str, int] = {}
    for joint in description.joints.values():
        kind = "d6_attachment" if joint.kind == "d6" and joint.exclude_from_articulation else joint.kind
        joints_by_kind[kind] = joints_by_kind.get(kind, 0) + 1
    shapes_by_kind: dict[str, int] = {}
    for body in bodies.values():
        for shape in body.shapes:
            shapes_by_kind[shape.kind] = shapes_by_kind.get(shape.kind, 0) + 1
    return {
        "stage": description.source,
        "up_axis": description.up_axis,
        "meters_per_unit": description.meters_per_unit,
        "gravity": list(description.gravity),
        "time_step": description.time_step,
        "rigid_bodies": {
            "dynamic": sorted(p for p, b in bodies.items() if b.kind == "dynamic"),
            "kinematic": sorted(p for p, b in bodies.items() if b.kind == "kinematic"),
            "static_colliders": sorted(p for p, b in bodies.items() if b.kind == "static"),
        },
        "collision_shapes": dict(sorted(shapes_by_kind.items())),
        "joints": dict(sorted(joints_by_kind.items())),
        "articulations": [{"path": a.path, "bodies": sorted(a.bodies),
                           "joints": sorted(a.joints),
                           "movable_joints": sorted(j for j in a.joints
                                                    if description.joints[j].kind in ("revolute", "prismatic"))}
                          for a in description.articulations],
        "surface_grippers": [{"path": g.path, "attachment_points": list(g.attachment_points)}
                             for g in description.surface_grippers],
        "attachment_joints": sorted(description.attachment_joints),
        "unsupported": [{"path": path, "reason": reason} for path, reason in description.unsupported],
    }


def simulate_report(stage_path: str, seconds: float) -> dict:
    """Step the stage with every drive at its authored target; how far did each dynamic body move?

    ``max_displacement`` is over the bodies outside articulations (the things that should
    rest); articulations are judged by ``drive_errors`` (|position - target| per driven joint).
    """
    from . import create_world

    with create_world(stage_path) as world:
        start = {path: world.prim_pose(path)[0] for path, handle in world.scene.bodies.items()
                 if handle.kind == "dynamic"}
        steps = int(round(seconds / world.time_step))
        for _ in range(steps):
            world.step()
        moved = {path: math.dist(position, world.prim_pose(path)[0]) for path, position in start.items()}
        free = [path for path in moved if world.scene.bodies[path].articulation is None]
        drive_errors = {}
        for articulation in world.scene.articulations.values():
            positions = world.joint_positions(articulation.path)
            for dof, drive in enumerate(articulation.drives):
                if drive is not None:
                    drive_errors[articulation.joint_paths[dof]] = abs(positions[dof] - drive.target_position)
    worst = max(free, key=moved.get) if free else None
    return {
        "seconds": steps * world.time_step,
        "steps": steps,
        "max_displacement": {"path": worst, "distance": moved[worst] if worst else 0.0},
        "displacements": dict(sorted(moved.items())),
        "drive_errors": dict(sorted(drive_errors.items())),
    }


def _print_human(report: dict, simulation: dict | None) -> None:
    bodies = report["rigid_bodies"]
    print(f"stage {report['stage']}")
    step = "1/60 s (default)" if report["time_step"] is None else f"{report['time_step']:g} s"
    gravity = ", ".join(f"{g:g}" for g in report["gravity"])
    print(f"  up axis {report['up_axis']}, {report['meters_per_unit']} m per unit, gravity ({gravity}) m/s^2, "
          f"time step {step}")
    print(f"rigid bodies: {len(bodies['dynamic'])} dynamic, {len(bodies['kinematic'])} kinematic, "
          f"{len(bodies['static_colliders'])} static colliders")
    for kind in ("dynamic", "kinematic", "static_colliders"):
        for path in bodies[kind]:
            print(f"  {kind.replace('_colliders', '')}: {path}")
    print("collision shapes: " + (", ".join(f"{n} {k}" for k, n in report["collision_shapes"].items()) or "none"))
    print("joints: " + (", ".join(f"{n} {k}" for k, n in report["joints"].items()) or "none"))
    print(f"articulations: {len(report['articulations'])}")
    for articulation in report["articulations"]:
        print(f"  {articulation['path']}: {len(articulation['bodies'])} bodies, movable joints "
              + (", ".join(articulation["movable_joints"]) or "none"))
    print(f"surface grippers: {len(report['surface_grippers'])}")
    for gripper in report["surface_grippers"]:
        print(f"  {gripper['path']}: {len(gripper['attachment_points'])} attachment points")
        for point in gripper["attachment_points"]:
            print(f"    {point}")
    print(f"unsupported prims: {len(report['unsupported'])}")
    for item in report["unsupported"]:
        print(f"  {item['path']}: {item['reason']}")
    if simulation is not None:
        worst = simulation["max_displacement"]
        print(f"simulated {simulation['seconds']:g} s ({simulation['steps']} steps), drives at their targets")
        if worst["path"] is not None:
            print(f"  largest displacement of a free body: {worst['path']} moved {worst['distance'] * 1000:.2f} mm")
        for path, distance in simulation["displacements"].items():
            print(f"  {path}: moved {distance * 1000:.2f} mm")
        for path, error in simulation["drive_errors"].items():
            print(f"  drive {path}: {error:.6g} from target")


def run_stage_command(stage_path: str, as_json: bool, simulate_seconds: float | None) -> int:
    """Print a stage's physics summary (and a rest test with ``simulate_seconds``); return the exit code."""
    from graphflow.usd.physics_import import load_description

    if simulate_seconds is not None and not (simulate_seconds >= 0 and math.isfinite(simulate_seconds)):
        print(f"graphflow stage: --simulate needs a non-negative number of seconds, got {simulate_seconds}",
              file=sys.stderr)
        return EXIT_BAD_INPUT
    from . import create_world
    from .health import NonFiniteState

    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", UnsupportedPrimWarning)   # listed in the report instead
            description = load_description(stage_path)
            with create_world(stage_path) as world:      # building names what the PyBullet world cannot hold
                description.unsupported[:] = world.description.unsupported
            report = stage_report(description)
            simulation = simulate_report(stage_path, simulate_seconds) if simulate_seconds is not None else None
    except StageError as error:
        print(f"graphflow stage: {error}", file=sys.stderr)
        return EXIT_BAD_INPUT
    except NonFiniteState as error:
        print(f"graphflow stage: {stage_path}: {error}", file=sys.stderr)
        return EXIT_RUNTIME
    if as_json:
        if simulation is not None:
            report["simulation"] = simulation
            report["max_displacement"] = simulation["max_displacement"]
        print(json.dumps(report, indent=2))
    else:
        _print_human(report, simulation)
    return EXIT_OK
