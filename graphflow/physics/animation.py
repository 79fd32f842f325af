"""``local_transform``/``set_local_transform`` of ``PyBulletWorld``: the animation nodes placing prims.

A prim the world simulates as a free or kinematic body (or an articulation
root) is teleported, at rest: an animation holds it while it runs, and physics
takes over from rest on arrival (Kit teleports the body to the authored xform
each frame). Any other Xformable prim gets its xform ops on the stage's
animation layer (``graphflow.usd.animation_layer``), so world poses and reads
of the stage follow. Refused, with the prim named: a link inside an
articulation, a collider or joint (placed by its body), a prim with simulated
bodies under it, and a change of a body's scale (PyBullet cannot rescale a
collision shape at run time).
"""
from __future__ import annotations

from graphflow.poses import Pose, as_vec3, compose, relative
from graphflow.world import WorldError

SCALE_TOLERANCE = 1e-9


def local_transform(world, prim_path: str):
    """(translation m, orientation (x, y, z, w), scale) in the parent prim's frame, as the world has it now."""
    units = world.description.meters_per_unit
    handle = world.scene.bodies.get(prim_path)
    if handle is not None:
        position, orientation = relative(world._parent_pose(prim_path), world._body_pose(handle))
        return position, orientation, _authored_scale(world, prim_path)
    translation, orientation, scale = world.animation_layer.local_transform(prim_path)
    return tuple(c * units for c in translation), orientation, scale


def set_local_transform(world, prim_path: str, translation, orientation, scale) -> None:
    handle = world.scene.bodies.get(prim_path)
    if handle is not None:
        _place_body(world, handle, translation, orientation, scale)
        return
    _refuse_simulated(world, prim_path)
    units = world.description.meters_per_unit
    world.animation_layer.write(prim_path, tuple(c / units for c in translation), orientation, scale)
    stale = [path for path in world._offsets if path == prim_path or path.startswith(prim_path + "/")]
    for path in stale:
        del world._offsets[path]
    world.prim_reader.forget(prim_path)


def _place_body(world, handle, translation, orientation, scale) -> None:
    if handle.link != -1:
        raise WorldError(f"{handle.path} is a link inside an articulation: only its root can be placed")
    if any(abs(a - b) > SCALE_TOLERANCE for a, b in zip(scale, _authored_scale(world, handle.path))):
        raise WorldError(f"{handle.path} is a simulated body: PyBullet cannot rescale its collision shapes "
                         "while running")
    x, y, z, w = (float(c) for c in orientation)
    local: Pose = (as_vec3(translation), (x, y, z, w))
    target = compose(compose(world._parent_pose(handle.path), local), handle.inertial_in_prim)
    world.client.resetBasePositionAndOrientation(handle.body_id, target[0], target[1])
    world.client.resetBaseVelocity(handle.body_id, (0.0, 0.0, 0.0), (0.0, 0.0, 0.0))


def _refuse_simulated(world, prim_path: str) -> None:
    """A collider, a joint or an ancestor of bodies moves with physics, not with its xform ops."""
    if world._collider_owner(prim_path) is not None:
        raise WorldError(f"{prim_path} is a collider of body {world._collider_owner(prim_path)}: "
                         "it moves with its body")
    if prim_path in world.description.joints:
        raise WorldError(f"{prim_path} is a joint: it is placed by the bodies it joins")
    prefix = prim_path.rstrip("/") + "/"
    below = next((path for path in world.scene.bodies if path.startswith(prefix)), None)
    if below is not None:
        raise WorldError(f"{prim_path} has the simulated body {below} under it: moving it would move the body, "
                         "which graphflow's world does not do (animate the body itself)")


def _authored_scale(world, prim_path: str):
    return world.animation_layer.local_transform(prim_path)[2]
