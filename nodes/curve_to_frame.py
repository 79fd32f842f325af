"""omni.graph.nodes.CurveToFrame: a tangent, up and out vector at every point of a set of polylines."""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._curves import add, cross, curve_spans, dot, normalized, scale, sub

SPEC = NodeSpec(
    id="omni.graph.nodes.CurveToFrame",
    version=1,
    description=(
        "For every point of each curve (curveVertexStarts / curveVertexCounts over curvePoints): tangent = the "
        "first edge's direction at the first point, the last edge's at the last, the normalised mean of the two "
        "edge directions in between; the first up is the unit vector perpendicular to the first tangent nearest "
        "the axis of its smallest component, out = up x tangent; each next up and out are the previous ones "
        "turned by the rotation that takes the previous tangent to the next (parallel transport, so the frame "
        "does not twist). A one-point curve gets tangent +Z, up +Y, out +X. Points no curve covers get zero "
        "vectors; no curves give empty arrays."),
    categories=("examples", "geometry:generator"),
    ui_name="Create Curve From Frame",
    inputs=(
        Attribute("curvePoints", "float[3][]", default=(), description="Points of all the curves"),
        Attribute("curveVertexCounts", "int[]", default=(), description="Number of points of each curve"),
        Attribute("curveVertexStarts", "int[]", default=(), description="Index of each curve's first point"),
    ),
    outputs=(
        Attribute("out", "float[3][]", description="Out vector at every point"),
        Attribute("tangent", "float[3][]", description="Tangent at every point"),
        Attribute("up", "float[3][]", description="Up vector at every point"),
    ),
)


def perpendicular(v):
    """The unit vector perpendicular to *v* closest to the axis of *v*'s smallest component."""
    a = [abs(c) for c in v]
    axis = 0 if a[0] < a[1] and a[0] < a[2] else (1 if a[1] < a[2] else 2)
    p = [0.0, 0.0, 0.0]
    p[axis] = 1.0
    if dot(v, v) == 0.0:    # a zero tangent (repeated points): any axis is perpendicular
        return tuple(p)
    return normalized(sub(p, scale(dot(p, v) / dot(v, v), v)))


def turned(v, a, a_plus_b):
    """*v* turned by the rotation taking unit tangent a to b: reflected through a, then through a + b."""
    mirrored = sub(scale(2.0 * dot(a, v), a), v)
    if dot(a_plus_b, a_plus_b) == 0.0:   # the curve doubles back: no unique turn, keep the vector
        return v
    return sub(scale(2.0 * dot(a_plus_b, mirrored) / dot(a_plus_b, a_plus_b), a_plus_b), mirrored)


def frames(points, start: int, count: int):
    """(tangents, ups, outs) of the curve points[start:start + count]."""
    if count == 1:
        return [(0.0, 0.0, 1.0)], [(0.0, 1.0, 0.0)], [(1.0, 0.0, 0.0)]
    edges = [normalized(sub(points[i + 1], points[i])) for i in range(start, start + count - 1)]
    tangents = [edges[0]] + [normalized(add(edges[i - 1], edges[i])) for i in range(1, count - 1)] + [edges[-1]]
    ups = [perpendicular(tangents[0])]
    outs = [cross(ups[0], tangents[0])]
    for previous, tangent in zip(tangents, tangents[1:]):
        middle = add(previous, tangent)
        ups.append(turned(ups[-1], previous, middle))
        outs.append(turned(outs[-1], previous, middle))
    return tangents, ups, outs


def compute(db):
    points, starts, counts = db.inputs.curvePoints, db.inputs.curveVertexStarts, db.inputs.curveVertexCounts
    if not starts or not counts:
        db.outputs.tangent = db.outputs.up = db.outputs.out = ()
        return
    zero = (0.0, 0.0, 0.0)
    tangents, ups, outs = [zero] * len(points), [zero] * len(points), [zero] * len(points)
    for start, count in curve_spans(starts, counts, len(points)):
        tangents[start:start + count], ups[start:start + count], outs[start:start + count] = \
            frames(points, start, count)
    db.outputs.tangent, db.outputs.up, db.outputs.out = tuple(tangents), tuple(ups), tuple(outs)
