"""omni.graph.nodes.GetLocationAtDistanceOnCurve2: the point and heading at a fraction of a closed polyline's length."""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._curves import AXIS_TOKENS, axis, closed_polyline, locate

DESCRIPTION = (
    "The curve's points joined in order and closed back to the first; distance is a fraction of its whole length "
    "(0 and 1 the first point; wrapped into [0, 1): -0.4 is 0.6, 1.3 is 0.3). location = that point; orientation "
    "= the rotation turning forwardAxis onto the segment's direction, with upAxis (the normal of the curve's "
    "plane) kept up; rotateXYZ = the same rotation as xformOp:rotateXYZ angles in degrees. Kit's C++ wraps "
    "with fmod, which keeps a negative fraction negative and extrapolates before the first point; graphflow "
    "wraps as Kit's reference page states. A one-point curve gives that point and no rotation; an empty curve "
    "fails the run.")

SPEC = NodeSpec(
    id="omni.graph.nodes.GetLocationAtDistanceOnCurve2",
    version=1,
    description=DESCRIPTION,
    categories=("internal",),
    ui_name="Get Locations At Distances On Curve",
    inputs=(
        Attribute("curve", "pointd[3][]", default=(), description="The curve's points (closed back to the first)"),
        Attribute("distance", "double", default=0.0, description="Fraction of the curve's length, wrapped to [0, 1)"),
        Attribute("forwardAxis", "token", default="X", allowed_tokens=AXIS_TOKENS,
                  description="The axis the orientation turns onto the curve's direction"),
        Attribute("upAxis", "token", default="Y", allowed_tokens=AXIS_TOKENS,
                  description="World up: the normal of the plane the curve lies in"),
    ),
    outputs=(
        Attribute("location", "pointd[3]", description="The point on the curve"),
        Attribute("orientation", "quatf[4]", description="The curve's heading there (x, y, z, w)"),
        Attribute("rotateXYZ", "vectord[3]", description="The heading as rotateXYZ angles (degrees)"),
    ),
)


def compute(db):
    if not db.inputs.curve:
        db.error("inputs:curve is empty: give the curve's points")
    polyline = closed_polyline(db.inputs.curve)
    forward, up = axis(db.inputs.forwardAxis), axis(db.inputs.upAxis)
    db.outputs.location, db.outputs.orientation, db.outputs.rotateXYZ = locate(
        polyline, db.inputs.distance, forward, up)
