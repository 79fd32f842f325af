"""omni.graph.nodes.LengthAlongCurve: the arc length from each curve's first point to every point on it."""
import math

from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._curves import curve_spans

SPEC = NodeSpec(
    id="omni.graph.nodes.LengthAlongCurve",
    version=1,
    description=(
        "outputs:length[p] = the polyline length from its curve's first point to point p (curves given by "
        "curveVertexStarts / curveVertexCounts over curvePoints, read pairwise); with normalize each curve's "
        "lengths are divided by its total, so they run from 0 to 1 (a zero-length curve is left unnormalised). The "
        "output has one entry per point; points no curve covers stay 0. No curves give an empty array."),
    categories=("geometry:analysis",),
    ui_name="Length Along Curve",
    inputs=(
        Attribute("curvePoints", "float[3][]", default=(), description="Points of all the curves"),
        Attribute("curveVertexCounts", "int[]", default=(), description="Number of points of each curve"),
        Attribute("curveVertexStarts", "int[]", default=(), description="Index of each curve's first point"),
        Attribute("normalize", "bool", default=False, description="Divide each curve's lengths by its total"),
    ),
    outputs=(
        Attribute("length", "float[]", description="Length along its curve at every point"),
    ),
)


def compute(db):
    points, starts, counts = db.inputs.curvePoints, db.inputs.curveVertexStarts, db.inputs.curveVertexCounts
    if not starts or not counts:
        db.outputs.length = ()
        return
    lengths = [0.0] * len(points)
    for start, count in curve_spans(starts, counts, len(points)):
        total = 0.0
        for i in range(start + 1, start + count):
            total += math.dist(points[i], points[i - 1])
            lengths[i] = total
        if db.inputs.normalize and total != 0.0:
            for i in range(start, start + count):
                lengths[i] /= total
    db.outputs.length = tuple(lengths)
