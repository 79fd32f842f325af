"""Helpers shared by the omni.graph.nodes curve and tube nodes (LengthAlongCurve, CurveToFrame, CurveTubePositions, ...).

Not a node type. Kit describes a set of curves as one flat point array plus two
int arrays: ``curveVertexStarts[i]`` (the index of curve i's first point) and
``curveVertexCounts[i]`` (how many points it has). Kit's nodes read the two
arrays pairwise up to the shorter one, skip a curve whose count is not
positive, stop at the first curve that starts past the end of the points and
clip a curve that runs past it; ``curve_spans`` is that rule, once.
"""
from __future__ import annotations

import math

from graphflow_nodes._matrices import matrix_euler, multiply, transpose
from graphflow_nodes._vectors import matrix_quaternion

AXES = {"X": (1.0, 0.0, 0.0), "Y": (0.0, 1.0, 0.0), "Z": (0.0, 0.0, 1.0)}
AXIS_TOKENS = ("X", "Y", "Z", "x", "y", "z")


def curve_spans(starts, counts, point_count: int) -> list[tuple[int, int]]:
    """(first point, point count) of each curve Kit's curve nodes visit, clipped to the points given."""
    spans = []
    for start, count in zip(starts, counts):
        if count <= 0:
            continue
        if start < 0 or start >= point_count:
            break
        spans.append((start, min(count, point_count - start)))
    return spans


def sub(a, b) -> tuple[float, float, float]:
    return a[0] - b[0], a[1] - b[1], a[2] - b[2]


def add(a, b) -> tuple[float, float, float]:
    return a[0] + b[0], a[1] + b[1], a[2] + b[2]


def scale(k: float, a) -> tuple[float, float, float]:
    return k * a[0], k * a[1], k * a[2]


def dot(a, b) -> float:
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def cross(a, b) -> tuple[float, float, float]:
    return a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]


def length(a) -> float:
    return math.sqrt(dot(a, a))


def normalized(a) -> tuple[float, float, float]:
    """*a* over its length; a zero vector stays zero (Gf's GetNormalized does the same)."""
    size = length(a)
    return scale(1.0 / size, a) if size > 0.0 else (0.0, 0.0, 0.0)


def axis(token: str) -> tuple[float, float, float]:
    """The unit vector a forwardAxis / upAxis token names; Kit reads anything but y/Y/z/Z as X."""
    return AXES.get(token.upper(), AXES["X"]) if token else AXES["X"]


def closed_polyline(curve) -> tuple[list, list[float], float]:
    """The curve's points with the first repeated at the end, each closing segment's length, and their sum."""
    points = [tuple(map(float, p)) for p in curve] + [tuple(map(float, curve[0]))]
    lengths = [math.dist(a, b) for a, b in zip(points, points[1:])]
    return points, lengths, sum(lengths)


def locate(polyline, fraction: float, forward, up):
    """(location, (x, y, z, w) orientation, rotateXYZ degrees) at *fraction* of a closed polyline's length.

    The fraction wraps into [0, 1) (-0.4 is 0.6, 1.3 is 0.3). The orientation turns *forward* onto the
    segment's direction about an up axis kept as near *up* as the direction allows.
    """
    points, lengths, total = polyline
    distance = total * (fraction % 1.0)
    reached = 0.0
    for i, segment in enumerate(lengths):
        if segment > 0.0 and reached + segment >= distance:
            direction = scale(1.0 / segment, sub(points[i + 1], points[i]))
            location = add(points[i], scale(distance - reached, direction))
            return location, *heading(direction, forward, up)
        reached += segment
    return points[0], (0.0, 0.0, 0.0, 1.0), (0.0, 0.0, 0.0)   # every point the same: no direction


def heading(direction, forward, up):
    """The rotation taking the frame (forward, up) to (direction, up made perpendicular to it), and its rotateXYZ."""
    def frame(u, v):
        w = normalized(cross(u, v))
        return u + cross(w, u) + w     # rows: u, v made perpendicular to u, u x v

    rotation = multiply(transpose(frame(forward, up), 3), frame(direction, up), 3)   # row vectors: local -> world
    padded = rotation[0:3] + (0.0,) + rotation[3:6] + (0.0,) + rotation[6:9] + (0.0, 0.0, 0.0, 0.0, 1.0)
    return matrix_quaternion(padded), matrix_euler(rotation, "XYZ")
