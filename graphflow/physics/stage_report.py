"""The data behind ``graphflow stage``: what a stage holds, and whether it rests when simulated.

Printing and exit codes live with the CLI (``graphflow/cli/stage.py``); the rest
test steps a PyBullet world, so it lives in the physics package.
"""
from __future__ import annotations

import math

from graphflow.usd.description import StageDescription


def stage_report(description: StageDescription, unsupported) -> dict:
    """The stage summary as a JSON-ready dict; *unsupported*: (path, reason) of everything the import and
    the world's build could not represent (``world.unsupported``)."""
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
                                                    if description.joints[j].kind in ("revolute", "prismatic")),
                           "undriven_joints": sorted(j for j in a.joints if description.joints[j].drive is None
                                                     and description.joints[j].kind in ("revolute", "prismatic"))}
                          for a in description.articulations],
        "surface_grippers": [{"path": g.path, "attachment_points": list(g.attachment_points)}
                             for g in description.surface_grippers],
        "attachment_joints": sorted(description.attachment_joints),
        "unsupported": [{"path": path, "reason": reason} for path, reason in unsupported],
        "ignored": [{"path": path, "what": what} for path, what in description.ignored],
    }


def simulate_report(stage_path: str, seconds: float) -> dict:
    """Step the stage with every drive at its authored target; how far did each dynamic body move?

    ``max_displacement`` is over the bodies outside articulations (the things that should
    rest); articulations are judged by ``drive_errors`` (|position - target| per driven joint).
    """
    from graphflow.physics import create_world

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
            targets = world.drive_targets[articulation.path].positions
            for dof, drive in enumerate(articulation.drives):
                if drive is not None:
                    drive_errors[articulation.joint_paths[dof]] = abs(positions[dof] - targets[dof])
    worst = max(free, key=moved.__getitem__) if free else None
    return {
        "seconds": steps * world.time_step,
        "steps": steps,
        "max_displacement": {"path": worst, "distance": moved[worst] if worst else 0.0},
        "displacements": dict(sorted(moved.items())),
        "drive_errors": dict(sorted(drive_errors.items())),
    }
