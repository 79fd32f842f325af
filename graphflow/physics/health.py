"""A diverged simulation is an error, not a trace full of NaN: the first non-finite body, by tick.

Links' poses follow from their multibody's base state and joint state, so checking those (one
or two PyBullet calls per multibody) covers every body of the stage.
"""
from __future__ import annotations

import math
from typing import Any

from graphflow.executor import GraphRuntimeError
from graphflow.world import WorldError


class NonFiniteState(GraphRuntimeError, WorldError):
    """A body's pose or velocity became NaN or infinite (exit code 1 from ``graphflow run``)."""


def health_plan(scene) -> list[tuple[int, str | None, tuple[int, ...], tuple[str, ...]]]:
    """Per dynamic multibody: (body id, its base's prim or None for a fixed base, joint indices, the prims
    they move)."""
    plan: dict[int, list[Any]] = {}
    for path, handle in sorted(scene.bodies.items()):
        if handle.kind != "dynamic":
            continue
        entry = plan.setdefault(handle.body_id, [handle.body_id, None, [], []])
        fixed = handle.articulation is not None and scene.articulations[handle.articulation].fixed_base
        if handle.link == -1 and not fixed:         # a fixed base does not move
            entry[1] = path
    for articulation in scene.articulations.values():
        moving = plan.get(articulation.body_id)
        if moving is not None:
            moving[2] = articulation.joint_indices
            moving[3] = tuple(scene.by_id.get((articulation.body_id, index), articulation.path)
                             for index in articulation.joint_indices)
    return [(body_id, base, tuple(joints), tuple(paths)) for body_id, base, joints, paths in plan.values()]


def first_non_finite(client, plan) -> str | None:
    """The first prim (in path order) whose pose or velocity is not finite, or None.

    A sum of floats is finite when every term is (NaN and infinities propagate), so one sum per
    multibody clears the common case; only a non-finite sum looks at the values one by one.
    """
    broken = []
    isfinite = math.isfinite
    for body_id, base, joints, paths in plan:
        if base is not None:
            position, orientation = client.getBasePositionAndOrientation(body_id)
            linear, angular = client.getBaseVelocity(body_id)
            if not isfinite(sum(position) + sum(orientation) + sum(linear) + sum(angular)) and not all(
                    isfinite(c) for c in (*position, *orientation, *linear, *angular)):
                broken.append(base)
                continue
        if joints:
            states = client.getJointStates(body_id, joints)
            if isfinite(sum([state[0] + state[1] for state in states])):
                continue
            for path, state in zip(paths, states):
                if not (isfinite(state[0]) and isfinite(state[1])):
                    broken.append(path)
    return min(broken) if broken else None
