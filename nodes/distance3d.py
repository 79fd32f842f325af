"""omni.graph.nodes.Distance3D: the distance between two 3D points (a single point broadcasts to an array)."""
import math

from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._vectors import is_vector

SPEC = NodeSpec(
    id="omni.graph.nodes.Distance3D",
    version=1,
    description=(
        "outputs:distance = |a - b| for 3D points; if one input is an array of points and the other a single "
        "point, the single point is used against each (an array of distances)."),
    categories=("math:operator",),
    ui_name="Distance3D",
    inputs=(
        Attribute("a", "any", description="Point A (or array of points)"),
        Attribute("b", "any", description="Point B (or array of points)"),
    ),
    outputs=(
        Attribute("distance", "any", description="The distance(s)"),
    ),
)


def _point(value) -> bool:
    return is_vector(value) and len(value) == 3


def compute(db):
    a, b = db.inputs.a, db.inputs.b
    if _point(a) and _point(b):
        db.outputs.distance = math.dist(a, b)
        return
    many_a = a if isinstance(a, tuple) and not _point(a) else None
    many_b = b if isinstance(b, tuple) and not _point(b) else None
    if many_a is not None and many_b is not None and len(many_a) != len(many_b):
        db.error(f"inputs:a and inputs:b: arrays of {len(many_a)} and {len(many_b)} points")
    count = len(many_a if many_a is not None else many_b or ())
    pairs = [((many_a[i] if many_a is not None else a), (many_b[i] if many_b is not None else b)) for i in range(count)]
    if not pairs or not all(_point(p) and _point(q) for p, q in pairs):
        db.error(f"inputs:a and inputs:b must be 3D points or arrays of them, got {a!r}, {b!r}")
    db.outputs.distance = tuple(math.dist(p, q) for p, q in pairs)
