"""Contact settings that make resting and dropped bodies behave at the stage's rate (60 Hz).

Measured with PyBullet 3.2.7 (a cube of 40-70 mm, 0.1-3 kg dropped 0.15 m; a 3-2-1 pyramid
of 40 mm cubes left 60 s), at a 60 Hz stage:

* one 1/60 s step lets a dropped cube sink 20-41 mm and take ~1 s to climb out; Bullet's
  contact solver needs a finer step: four internal steps (240 Hz) give 2.7 mm and rest within
  0.22 s. ``internal_substeps`` picks the smallest count whose internal step is at most
  ``MAX_INTERNAL_STEP``; an authored ``physxScene:timeStepsPerSecond`` of 240 Hz or more
  therefore needs no substep, and the graph's ``settings.substeps`` overrides the choice;
* without a friction anchor Bullet re-creates friction constraints at every contact point
  each step, so resting bodies creep (a pyramid: 2-3 mm in 60 s even at 480 Hz); the
  anchor keeps them where they touched (0.05 mm), so every dynamic body gets one;
* PyBullet's infinite plane shape (GEOM_PLANE) penetrates 3x deeper and lets cubes creep
  100x more than a box ground at the same settings, so a ``UsdGeom.Plane`` collider (infinite
  in UsdPhysics) becomes a large static box whose top face is the plane.
"""
from __future__ import annotations

import math

SOLVER_RESIDUAL = 3e-7               # (m/s)^2: the solver stops iterating below this summed squared correction
MAX_INTERNAL_STEP = 1.0 / 240.0        # s: the coarsest PyBullet step at which contacts meet the targets
PLANE_HALF_WIDTH = 500.0               # m: a UsdGeom.Plane collider's box reaches this far from its origin
PLANE_HALF_THICKNESS = 5.0             # m: and this deep below the plane
ROLLING_SHAPES = ("cylinder", "capsule", "cone")   # colliders that roll on their side: no friction anchor


def internal_substeps(time_step: float) -> int:
    """PyBullet steps per stage step so that each is at most ``MAX_INTERNAL_STEP`` long."""
    return max(1, math.ceil(time_step / MAX_INTERNAL_STEP - 1e-9))


def plane_box(axis: str) -> tuple[list[float], list[float]]:
    """(half extents, centre offset) of the box that stands for a plane whose normal is +*axis*."""
    index = "XYZ".index(axis)
    half_extents = [PLANE_HALF_WIDTH] * 3
    half_extents[index] = PLANE_HALF_THICKNESS
    centre = [0.0, 0.0, 0.0]
    centre[index] = -PLANE_HALF_THICKNESS
    return half_extents, centre


def anchor_friction(client, body_id: int, link: int) -> None:
    """Keep a dynamic body's friction contacts anchored where they were made (no resting creep).

    Not for what rolls: an anchor holds a contact to the material point where it was made, and on a
    rolling body that point moves away and is pulled back along the roll, which drives it. A free
    cylinder on its side rolled 3.25 m in 10 s with anchors (0.51 m without: Bullet's line contact
    gives it an initial push), and a four-wheel robot on free wheels accelerated at 0.17 m/s^2 on flat
    ground. So bodies with a ``ROLLING_SHAPES`` collider and articulation links on revolute joints
    (wheels, whatever their collider) get none."""
    client.changeDynamics(body_id, link, frictionAnchor=1)


def solver_iterations(authored: dict[str, int], default: int) -> int:
    """PyBullet's one iteration count from PhysX's authored counts.

    PhysX iterates each body or articulation its own ``solverPositionIterationCount`` times,
    clamped to the scene's ``[minPositionIterationCount, maxPositionIterationCount]``; PyBullet
    has one count for the whole world, so it takes the largest authored per-body count (never
    fewer than *default*, which the contact targets were measured with), clamped likewise.
    """
    count = max(default, authored.get("bodies", 0))
    count = max(count, authored.get("sceneMin", 1))
    return max(1, min(count, authored.get("sceneMax", count)))
