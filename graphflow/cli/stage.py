"""``graphflow stage STAGE.usda [--json] [--simulate SECONDS]``: what a stage holds, and whether it rests.

The command side: argument checks, one line on stderr for a bad stage, the
human and JSON printouts, exit codes (0 ok, 1 the simulation diverged, 2 bad input). The report data comes
from ``graphflow.physics.stage_report`` (usd-core and PyBullet, imported only here,
when the command runs).
"""
from __future__ import annotations

import json
import math
import sys
import warnings
from pathlib import Path

from graphflow.cli import arguments
from graphflow.errors import EXIT_BAD_INPUT, EXIT_OK, EXIT_RUN_FAILED
from graphflow.world import DEFAULT_TIME_STEP

DRIVE_TOLERANCE = 0.01   # rad or m: a drive this near its target after the rest test is "at" it


def register(commands) -> None:
    stage = commands.add_parser("stage", help="show what the importer makes of a USD stage")
    stage.add_argument("stage", help=".usda / .usd file, or asset:NAME for a packaged stage")
    stage.add_argument("--json", action="store_true", help="print one JSON object")
    stage.add_argument("--simulate", type=arguments.seconds, metavar="SECONDS",
                       help="step the stage with drives at their targets and report how far bodies moved")
    stage.add_argument("--allow-missing-assets", action="store_true",
                       help="a reference, payload or sublayer that cannot be opened is a warning, not a failure")
    stage.set_defaults(handler=command_stage)


def command_stage(args) -> int:
    from graphflow.usd.opening import missing_layers_refused

    with missing_layers_refused(not args.allow_missing_assets):
        return run_stage_command(args.stage, as_json=args.json, simulate_seconds=args.simulate)


def run_stage_command(stage_path: str, as_json: bool, simulate_seconds: float | None) -> int:
    """Print a stage's physics summary (and a rest test with ``simulate_seconds``); return the exit code."""
    from graphflow.physics import create_world
    from graphflow.physics.health import NonFiniteState
    from graphflow.physics.stage_report import simulate_report, stage_report
    from graphflow.usd.errors import StageError, UnsupportedPrimWarning
    from graphflow.usd.physics_import import load_description
    from graphflow.usd.resolver import resolve_stage

    if simulate_seconds is not None and not (simulate_seconds >= 0 and math.isfinite(simulate_seconds)):
        print(f"graphflow stage: --simulate needs a non-negative number of seconds, got {simulate_seconds}",
              file=sys.stderr)
        return EXIT_BAD_INPUT
    try:
        stage_path = str(resolve_stage(stage_path, Path.cwd()))
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", UnsupportedPrimWarning)   # listed in the report instead
            description = load_description(stage_path)
            with create_world(stage_path) as world:   # building also names what the PyBullet world cannot hold
                report = stage_report(description, world.unsupported)
            simulation = simulate_report(stage_path, simulate_seconds) if simulate_seconds is not None else None
    except StageError as error:
        for problem in error.problems:
            print(f"graphflow stage: {problem}", file=sys.stderr)
        return EXIT_BAD_INPUT
    except NonFiniteState as error:
        print(f"graphflow stage: {stage_path}: {error}", file=sys.stderr)
        return EXIT_RUN_FAILED
    if as_json:
        if simulation is not None:
            report["simulation"] = simulation
            report["max_displacement"] = simulation["max_displacement"]
        print(json.dumps(report, indent=2))
    else:
        print_stage_report(report, simulation)
    return EXIT_OK


def drives_verdict(report: dict, simulation: dict) -> str:
    """What the rest test says of the articulations: limp (joints, no drive), or how near the drives held."""
    movable = sum(len(articulation["movable_joints"]) for articulation in report["articulations"])
    free = sum(len(articulation["undriven_joints"]) for articulation in report["articulations"])
    errors = simulation["drive_errors"]
    if not movable:
        return "no articulated joints"
    if not errors:
        return (f"limp: {movable} articulated joints and no drive, every joint falls free "
                "(graphflow robot add gives a converted arm drives)")
    worst = max(errors, key=errors.get)
    held = (f"drives at their targets (within {DRIVE_TOLERANCE:g})" if errors[worst] <= DRIVE_TOLERANCE
            else f"drives short of their targets: {worst} {errors[worst]:.4g} from target")
    return held + (f"; {free} joints without a drive free" if free else "")


def print_stage_report(report: dict, simulation: dict | None) -> None:
    """The human-readable summary (and rest test) of ``graphflow stage``."""
    bodies = report["rigid_bodies"]
    print(f"stage {report['stage']}")
    step = f"1/{1 / DEFAULT_TIME_STEP:.0f} s (default)" if report["time_step"] is None else f"{report['time_step']:g} s"
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
        if articulation["undriven_joints"]:
            print("    without a drive (free): " + ", ".join(articulation["undriven_joints"]))
    print(f"surface grippers: {len(report['surface_grippers'])}")
    for gripper in report["surface_grippers"]:
        print(f"  {gripper['path']}: {len(gripper['attachment_points'])} attachment points")
        for point in gripper["attachment_points"]:
            print(f"    {point}")
    print(f"unsupported prims: {len(report['unsupported'])}")
    for item in report["unsupported"]:
        print(f"  {item['path']}: {item['reason']}")
    print(f"ignored (other simulators' authoring): {len(report['ignored'])}")
    for item in report["ignored"]:
        print(f"  {item['path']}: {item['what']}")
    if simulation is not None:
        worst = simulation["max_displacement"]
        print(f"simulated {simulation['seconds']:g} s ({simulation['steps']} steps), {drives_verdict(report, simulation)}")
        if worst["path"] is not None:
            print(f"  largest displacement of a free body: {worst['path']} moved {worst['distance'] * 1000:.2f} mm")
        for path, distance in simulation["displacements"].items():
            print(f"  {path}: moved {distance * 1000:.2f} mm")
        for path, error in simulation["drive_errors"].items():
            print(f"  drive {path}: {error:.6g} from target")
