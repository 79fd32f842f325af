"""omni.graph.nodes.CurveTubePositions: the points of tubes swept around curves (a ring of cols points per curve point)."""
import math

from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._curves import add, scale

SPEC = NodeSpec(
    id="omni.graph.nodes.CurveTubePositions",
    version=1,
    description=(
        "Tube t follows curve t (curveVertexStarts[t], curveVertexCounts[t] over curvePoints) and owns output "
        "points tubePointStarts[t] up to tubePointStarts[t+1] (tubePointStarts has one more entry than there are "
        "tubes; its last is the output size): around curve point j a ring of cols points, column c at "
        "point_j + width_j/2 * (cos(2 pi c/cols) * out_j + sin(2 pi c/cols) * up_j). cols, width, up and out "
        "hold one value for every tube / curve point or a single value for all. A tube whose point range is "
        "not (curve points x cols) is skipped (its points stay at the origin); tube and curve counts that "
        "differ, or no positive cols, give an empty array. CurveToFrame gives up and out."),
    categories=("geometry:generator",),
    ui_name="Curve Tube Positions",
    inputs=(
        Attribute("cols", "int[]", default=(), description="Points around each tube (one value, or one per tube)"),
        Attribute("curvePoints", "float[3][]", default=(), description="Points of the curves the tubes follow"),
        Attribute("curveVertexCounts", "int[]", default=(), description="Number of points of each curve"),
        Attribute("curveVertexStarts", "int[]", default=(), description="Index of each curve's first point"),
        Attribute("out", "float[3][]", default=(), description="Out vector at each curve point (or one for all)"),
        Attribute("tubePointStarts", "int[]", default=(),
                  description="Index of each tube's first output point, then the total"),
        Attribute("up", "float[3][]", default=(), description="Up vector at each curve point (or one for all)"),
        Attribute("width", "float[]", default=(), description="Tube diameter at each curve point (or one for all)"),
    ),
    outputs=(
        Attribute("points", "float[3][]", description="The tube points"),
    ),
)


def ring(columns: int) -> list[tuple[float, float]]:
    """(cos, sin) of the columns of a ring, column 0 at angle 0."""
    return [(math.cos(2.0 * math.pi * c / columns), math.sin(2.0 * math.pi * c / columns)) for c in range(columns)]


def per_point(values, index: int):
    return values[0] if len(values) == 1 else values[index]


def compute(db):
    inputs = db.inputs
    starts, counts, points = inputs.curveVertexStarts, inputs.curveVertexCounts, inputs.curvePoints
    tube_starts, cols, up, out, width = inputs.tubePointStarts, inputs.cols, inputs.up, inputs.out, inputs.width
    tube_count = len(tube_starts) - 1
    total = tube_starts[-1] if tube_starts else 0
    if (total <= 0 or tube_count <= 0 or tube_count != min(len(starts), len(counts))
            or len(cols) not in (1, tube_count) or (len(cols) == 1 and cols[0] <= 0)
            or not points or not up or not out or not width):
        db.outputs.points = ()
        return
    result = [(0.0, 0.0, 0.0)] * total
    for tube in range(tube_count):
        first, end, curve, count = tube_starts[tube], tube_starts[tube + 1], starts[tube], counts[tube]
        columns = cols[0] if len(cols) == 1 else cols[tube]
        if min(first, curve, count) < 0 or columns <= 0:
            continue
        if end > total or end < first:
            break
        last = curve + count - 1
        if count * columns != end - first or count == 0 or last >= len(points) or any(
                len(values) != 1 and last >= len(values) for values in (up, out, width)):
            continue
        circle = ring(columns)
        for j in range(count):
            p = curve + j
            center, radius = points[p], 0.5 * per_point(width, p)
            u, o = per_point(up, p), per_point(out, p)
            for c, (cos, sin) in enumerate(circle):
                result[first + j * columns + c] = add(center, add(scale(radius * cos, o), scale(radius * sin, u)))
    db.outputs.points = tuple(result)
