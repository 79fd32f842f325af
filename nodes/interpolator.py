"""omni.graph.nodes.Interpolator: a value read off a piecewise-linear curve of time samples."""
from bisect import bisect_right

from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.Interpolator",
    version=1,
    description=(
        "outputs:value = the curve through (knots[i], values[i]) at param, linear between knots (sorted, "
        "increasing) and held at the first or last value outside them. Knots and values must be as long."),
    categories=("math:operator",),
    ui_name="Interpolator",
    inputs=(
        Attribute("knots", "float[]", default=(), description="The sample times, increasing"),
        Attribute("param", "float", default=0.0, description="Where to read the curve"),
        Attribute("values", "float[]", default=(), description="The sample values"),
    ),
    outputs=(
        Attribute("value", "float", description="The interpolated value"),
    ),
)


def compute(db):
    knots, values, t = db.inputs.knots, db.inputs.values, db.inputs.param
    if not knots or len(knots) != len(values):
        db.error(f"inputs:knots ({len(knots)}) and inputs:values ({len(values)}) must be as long, and not empty")
    if any(b < a for a, b in zip(knots, knots[1:])):
        db.error("inputs:knots must increase")
    i = bisect_right(knots, t)
    if i == 0:
        db.outputs.value = values[0]
    elif i == len(knots):
        db.outputs.value = values[-1]
    else:
        t0, t1 = knots[i - 1], knots[i]
        db.outputs.value = values[i - 1] + (values[i] - values[i - 1]) * (t - t0) / (t1 - t0)
