"""The trace's scene section (format version 2): what a run report needs to redraw a run.

Written by ``graphflow.observe.recorder.TraceRecorder`` beside its version-1 fields, so the
recorder itself stays small: the header's ``scene`` (every body's shapes and
starting pose, which bodies move, the pose sampling rate), and per tick the
nodes that computed, the moving bodies' poses (every ``poseEvery``-th tick,
changed ones only) and, on the tick a surface gripper starts to close, each
attachment point's ray with its reach and the nearest surface along it.
Everything is read from the world's declared interface and the stage
description; nothing is timed, so the section is as deterministic as the rest.
"""
from __future__ import annotations

from typing import Any

from graphflow.poses import AXIS_VECTORS, quat_rotate

POSE_EVERY = 4            # ticks between pose samples (scene.poseEvery): 15 Hz at 60 ticks/s; the page interpolates
RAY_PROBE = 1.0           # m a recorded ray is followed to find its nearest surface (the gripper's PROBE_RANGE)
SELF_STEP = 0.001         # m a recorded ray's origin advances past the gripper's own body (as the gripper's loop)
SELF_STEPS = 200          # give up after this many self hits (20 cm): a ray inside the gripper shows no hit


def _pose_list(pose) -> list[float]:
    (x, y, z), (qx, qy, qz, qw) = pose
    return [float(x), float(y), float(z), float(qx), float(qy), float(qz), float(qw)]


def _shape(shape) -> dict:
    """One collision shape in its body's frame: kind, local pose and the sizes that kind has."""
    item: dict[str, Any] = {"path": shape.path, "kind": shape.kind, "pose": _pose_list(shape.pose)}
    if shape.kind == "box":
        item["halfExtents"] = [float(v) for v in shape.half_extents]
    elif shape.kind == "sphere":
        item["radius"] = float(shape.radius)
    elif shape.kind in ("capsule", "cylinder", "cone"):
        item.update(radius=float(shape.radius), halfHeight=float(shape.half_height), axis=shape.axis)
    elif shape.kind == "plane":
        item["axis"] = shape.axis
    else:   # convex_mesh, triangle_mesh
        item["points"] = [[float(c) for c in point] for point in shape.points]
        if shape.triangles:
            item["triangles"] = [list(triangle) for triangle in shape.triangles]
    return item


def force_limits(component) -> dict[str, float]:
    """A surface gripper's force limits that are set (N), by name, as the force lane draws them."""
    properties = component.properties
    limits = {"force": properties.force_limit, "shear": properties.shear_force_limit,
              "coaxial": properties.coaxial_force_limit}
    return {name: float(value) for name, value in limits.items() if value > 0}


class SceneSection:
    """Collects the scene fields of a trace for one simulation; ``header()`` once, ``capture()`` after each tick."""

    def __init__(self, simulation, pose_every: int = POSE_EVERY):
        self.world = simulation.world
        self.instance = simulation.instance
        self.pose_every = pose_every
        description = getattr(self.world, "description", None)
        self.bodies = dict(getattr(description, "bodies", {}) or {})
        self.moving = [path for path, body in self.bodies.items() if body.kind != "static"]
        self._poses: dict[str, list[float]] = {}
        self._counts = list(self.instance.compute_counts)

    def header(self) -> dict:
        """``scene``: up axis, pose rate, each body's kind, pose and shapes (description order), articulation links."""
        if not self.bodies:
            return {}
        bodies = []
        for path, body in self.bodies.items():
            pose = _pose_list(self.world.prim_pose(path))
            if path in self.moving:
                self._poses[path] = pose
            bodies.append({"path": path, "kind": body.kind, "pose": pose, "shapes": [_shape(s) for s in body.shapes]})
        description = self.world.description
        links = sorted({path for articulation in description.articulations for path in articulation.bodies})
        return {"scene": {"upAxis": description.up_axis, "poseEvery": self.pose_every, "bodies": bodies, "links": links}}

    def capture(self, closing: list | None, row: list) -> tuple:
        """Append the compute counts to *row* (a list of plain values, copied right after); return what else
        ``encode`` needs of this tick, read now: the sampled poses (read now, composed when encoded) or None,
        the rays of the surface grippers in *closing* (those whose close began this tick) or None."""
        row.append(self.instance.compute_counts)
        poses = None
        if self.moving and self.instance.tick_count % self.pose_every == 0:
            poses = self.world.read_body_poses(self.moving)
        return poses, self._rays(closing) if closing else None

    def encode(self, counts: list, sampled, rays: dict | None) -> dict:
        """A tick's ``computed`` nodes, sampled ``poses`` that changed and ``rays``, from its capture."""
        record: dict[str, Any] = {}
        computed = [node.name for node, before, now in zip(self.instance.compiled.nodes, self._counts, counts)
                    if now != before]
        self._counts = counts
        if computed:
            record["computed"] = computed
        if sampled is not None:
            poses = {}
            for path, (position, orientation) in zip(self.moving, sampled()):
                pose = [*map(float, position), *map(float, orientation)]
                if pose != self._poses.get(path):
                    poses[path] = self._poses[path] = pose
            if poses:
                record["poses"] = poses
        if rays:
            record["rays"] = rays
        return record

    def _rays(self, closing: list) -> dict:
        return {component.path: {"limits": force_limits(component), "rays": close_rays(self.world, component)}
                for component in closing}


def close_rays(world, component) -> list[dict]:
    """A surface gripper's attachment points' rays as it casts them on a close (the trace's and live frames' ``rays``)."""
    return [_ray(world, component, point) for point in component.points]


def _ray(world, component, point) -> dict:
    """One attachment point's ray as the gripper casts it: origin, direction, reach, nearest surface."""
    frame = world.attachments.frame(point.body0_path, point.local_pose0)
    if frame is None:
        return {"point": point.joint_path, "origin": None, "direction": None, "reach": None, "hit": None}
    direction = quat_rotate(frame[1], AXIS_VECTORS[point.forward_axis])
    clearance = point.clearance_offset
    properties = component.properties
    reach = properties.max_grip_distance - (0.0 if properties.reach_from_ray_origin else clearance)
    origin = [float(frame[0][i] + direction[i] * clearance) for i in range(3)]
    hit = None
    start = origin
    for step in range(SELF_STEPS):
        found = world.raycast(tuple(start), tuple(direction), RAY_PROBE)
        if found is None or not found.prim_path:
            break
        if not world.same_body(found.prim_path, point.body0_path):
            hit = {"prim": found.prim_path, "distance": float(found.distance) + step * SELF_STEP}
            break
        start = [start[i] + direction[i] * SELF_STEP for i in range(3)]
    return {"point": point.joint_path, "origin": origin, "direction": [float(c) for c in direction],
            "reach": float(max(reach, 0.001)), "hit": hit}
