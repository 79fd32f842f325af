"""Choosing the base of an articulation that is free in space (which body PyBullet's multibody hangs from)."""
from __future__ import annotations

from graphflow.usd.description import Joint


def floating_root(articulation, members: list[str], joints: list[Joint]) -> str:
    """The base body of an articulation free in space.

    usd-core's root prim when it is a body of the articulation (the ArticulationRootAPI body, or for an
    API on an ancestor the body it picks: the krabby's chassis); otherwise the centre of the joint graph
    (the body with the smallest largest hop count to any other body), ties broken by path.
    """
    for root in articulation.roots:
        if root in members:
            return root
    if articulation.path in members:
        return articulation.path
    neighbours: dict[str, list[str]] = {body: [] for body in members}
    for joint in joints:
        if joint.body0 in neighbours and joint.body1 in neighbours:
            neighbours[joint.body0].append(joint.body1)
            neighbours[joint.body1].append(joint.body0)

    def eccentricity(body: str) -> int:
        hops, frontier = {body: 0}, [body]
        while frontier:
            current = frontier.pop(0)
            for other in neighbours[current]:
                if other not in hops:
                    hops[other] = hops[current] + 1
                    frontier.append(other)
        return max(hops.values())

    return min(sorted(members), key=eccentricity)
