"""Prims switched off and on while running (SetPrimActive), and what the world does instead of removing them.

Isaac deactivating a prim takes it off the composed stage and PhysX drops its
bodies; activating it again brings them back at rest. A PyBullet body cannot
leave the client without invalidating every handle the world, its lookups and
the recorder hold, so a deactivated dynamic free body stays in the client made
static (mass 0) and without collisions (filter group and mask 0: nothing
touches it and rays pass through it). Activated again it gets its mass and
Bullet's collision filter for a dynamic body back, at rest where it was. Every
rigid body under the prim is switched; articulation links, kinematic and static
bodies and bodies a joint holds are refused with the reason. A prim holding no
body only changes what ``prim_active`` (IsPrimActive) reads. The world's reset
rebuilds the client, so every prim is active again after it.
"""
from __future__ import annotations

from graphflow.world import WorldError

DYNAMIC_FILTER_GROUP, ALL_FILTER_MASK = 1, -1   # Bullet's collision filter of a dynamic body (DefaultFilter, AllFilter)


class PrimActivity:
    """The prims of one build that a graph switched off, and switching them (the world's, rebuilt with it)."""

    def __init__(self, world):
        self.world = world
        self.inactive: set[str] = set()
        self._inertia: dict[str, tuple] = {}       # switched-off body -> its local inertia diagonal, to give back

    def is_active(self, path: str) -> bool:
        prim = self._prim(path)
        return bool(prim.IsActive()) and not any(_under(path, off) for off in self.inactive)

    def set_active(self, path: str, active: bool) -> None:
        self._prim(path)
        bodies = [handle for body_path, handle in self.world.scene.bodies.items() if _under(body_path, path)]
        for handle in bodies:
            self._check_switchable(handle)
        if active == self.is_active(path):
            return
        for handle in bodies:
            self._switch(handle, active)
        if active:
            self.inactive = {off for off in self.inactive if not _under(off, path)}
        else:
            self.inactive.add(path)

    def _prim(self, path: str):
        stage = self.world.stage
        prim = stage.GetPrimAtPath(path) if stage is not None and path.startswith("/") else None
        if not prim:
            raise WorldError(f"no prim {path} on this stage")
        return prim

    def _check_switchable(self, handle) -> None:
        if handle.articulation is not None or handle.link != -1:
            raise WorldError(f"{handle.path} is part of the articulation {handle.articulation}: graphflow's world "
                             "cannot take one out of the simulation while running")
        if handle.kind != "dynamic":
            raise WorldError(f"{handle.path} is a {handle.kind} body: only dynamic free bodies can be switched off "
                             "while running")
        for joint in self.world.description.joints.values():
            if handle.path in (joint.body0, joint.body1) and joint.path in self.world.scene.constraints:
                raise WorldError(f"{handle.path} is held by the joint {joint.path}: graphflow's world cannot take "
                                 "a jointed body out of the simulation while running")

    def _switch(self, handle, active: bool) -> None:
        client = self.world.client
        client.resetBaseVelocity(handle.body_id, (0.0, 0.0, 0.0), (0.0, 0.0, 0.0))
        if active:      # PyBullet recomputes a base's inertia from its shape when its mass changes: set it back
            client.changeDynamics(handle.body_id, -1, mass=self.world.masses[handle.path],
                                  localInertiaDiagonal=list(self._inertia.pop(handle.path)))
        else:
            self._inertia[handle.path] = tuple(client.getDynamicsInfo(handle.body_id, -1)[2])
            client.changeDynamics(handle.body_id, -1, mass=0.0)
        group, mask = (DYNAMIC_FILTER_GROUP, ALL_FILTER_MASK) if active else (0, 0)
        client.setCollisionFilterGroupMask(handle.body_id, -1, group, mask)


def _under(path: str, root: str) -> bool:
    return path == root or path.startswith(root.rstrip("/") + "/")
