"""omni.graph.nodes.CurveTubeST: texture coordinates (s around, t along) for tubes swept around curves."""
import math

from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.CurveTubeST",
    version=1,
    description=(
        "Tube t follows curve t (curveVertexStarts / curveVertexCounts) and owns st values tubeSTStarts[t] up to "
        "tubeSTStarts[t+1] and quads tubeQuadStarts[t] up to tubeQuadStarts[t+1] (both lists end with the total). "
        "Around curve point j a ring of cols + 1 st values (the seam twice): s = c/cols for c = 0 to cols, "
        "t = t[j], times 1/(width * cols * sin(pi/cols)) with scaleTLikeS so t advances like s does on the "
        "surface (width: one value, one per tube, or one per curve point, where the curve's largest is used). "
        "Quad k of a tube, column c, ring r indexes st values (i, i + 1, i + cols + 2, i + cols + 1) with "
        "i = the tube's first + r * (cols + 1) + c. A tube whose st range is not (curve points x (cols + 1)) is "
        "skipped; inconsistent counts, no positive cols or no t values give empty arrays. Kit's outputs "
        "primvars:st and primvars:st:indices are primvars_st and primvars_st_indices here (the names Kit's "
        "Python database uses); graphflow import and og compat map the colon names."),
    categories=("geometry:generator",),
    ui_name="Curve Tube ST",
    inputs=(
        Attribute("cols", "int[]", default=(), description="Points around each tube (one value, or one per tube)"),
        Attribute("curveVertexCounts", "int[]", default=(), description="Number of points of each curve"),
        Attribute("curveVertexStarts", "int[]", default=(), description="Index of each curve's first point"),
        Attribute("scaleTLikeS", "bool", default=False, description="Scale t by the tube's circumference, as s is"),
        Attribute("t", "float[]", default=(), description="t at each curve point (e.g. LengthAlongCurve's length)"),
        Attribute("tubeQuadStarts", "int[]", default=(), description="Index of each tube's first quad, then the total"),
        Attribute("tubeSTStarts", "int[]", default=(), description="Index of each tube's first st value, then the total"),
        Attribute("width", "float[]", default=(), description="Tube diameters, used when scaleTLikeS"),
    ),
    outputs=(
        Attribute("primvars_st", "float[2][]", description="The st values (Kit's outputs:primvars:st)"),
        Attribute("primvars_st_indices", "int[]", description="Four st indices per quad (Kit's outputs:primvars:st:indices)"),
    ),
)


def t_width(widths, tube: int, tube_count: int, curve: int, count: int, t_count: int) -> float:
    if len(widths) == tube_count:
        return widths[tube]
    if len(widths) == t_count:
        return max(widths[curve:curve + count])
    return widths[0]


def compute(db):
    inputs = db.inputs
    starts, counts, cols, t_values = inputs.curveVertexStarts, inputs.curveVertexCounts, inputs.cols, inputs.t
    widths = inputs.width
    tube_count = min(len(inputs.tubeSTStarts), len(inputs.tubeQuadStarts))
    st_starts, quad_starts = inputs.tubeSTStarts[:tube_count], inputs.tubeQuadStarts[:tube_count]
    st_total, quad_total = (st_starts[-1], quad_starts[-1]) if tube_count else (0, 0)
    tube_count -= 1
    scale_t = inputs.scaleTLikeS and len(widths) in (1, len(t_values), tube_count) and bool(widths)
    if (st_total <= 0 or tube_count <= 0 or tube_count != min(len(starts), len(counts)) or not t_values
            or len(cols) not in (1, tube_count) or (len(cols) == 1 and cols[0] <= 0)):
        db.outputs.primvars_st, db.outputs.primvars_st_indices = (), ()
        return
    st = [(0.0, 0.0)] * st_total
    indices = [0] * (4 * max(quad_total, 0))
    for tube in range(tube_count):
        first, end, curve, count = st_starts[tube], st_starts[tube + 1], starts[tube], counts[tube]
        columns = cols[0] if len(cols) == 1 else cols[tube]
        if min(first, curve, quad_starts[tube], count) < 0 or columns <= 0:
            continue
        if end > st_total or end < first:
            break
        if count * (columns + 1) != end - first or curve + count > len(t_values) or quad_starts[tube + 1] > quad_total:
            continue
        t_scale = 1.0
        if scale_t:
            width = t_width(widths, tube, tube_count, curve, count, len(t_values))
            t_scale = 1.0 / (width * columns * math.sin(math.pi / columns))
        for j in range(count):
            t = t_scale * t_values[curve + j]
            for c in range(columns + 1):
                st[first + j * (columns + 1) + c] = (c / columns, t)
        for quad in range(quad_starts[tube], quad_starts[tube + 1]):
            row, column = divmod(quad - quad_starts[tube], columns)
            i = first + row * (columns + 1) + column
            indices[4 * quad:4 * quad + 4] = (i, i + 1, i + columns + 2, i + columns + 1)
    db.outputs.primvars_st, db.outputs.primvars_st_indices = tuple(st), tuple(indices)
