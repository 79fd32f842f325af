"""omni.graph.nodes.GetLocationAtDistanceOnCurve: GetLocationAtDistanceOnCurve2 for an array of distances (deprecated in Kit)."""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._curves import AXIS_TOKENS, axis, closed_polyline, locate

SPEC = NodeSpec(
    id="omni.graph.nodes.GetLocationAtDistanceOnCurve",
    version=1,
    description=(
        "Kit's deprecated form of GetLocationAtDistanceOnCurve2 taking an array of distances: one location, "
        "orientation and rotateXYZ per distance, each computed as GetLocationAtDistanceOnCurve2 does (the curve "
        "closed back to its first point, each distance a fraction of its length wrapped into [0, 1))."),
    categories=("internal",),
    ui_name="Get Locations At Distances On Curve",
    inputs=(
        Attribute("curve", "pointd[3][]", default=(), description="The curve's points (closed back to the first)"),
        Attribute("distance", "double[]", default=(), description="Fractions of the curve's length, wrapped to [0, 1)"),
        Attribute("forwardAxis", "token", default="X", allowed_tokens=AXIS_TOKENS,
                  description="The axis the orientations turn onto the curve's direction"),
        Attribute("upAxis", "token", default="Y", allowed_tokens=AXIS_TOKENS,
                  description="World up: the normal of the plane the curve lies in"),
    ),
    outputs=(
        Attribute("location", "pointd[3][]", description="The points on the curve"),
        Attribute("orientation", "quatf[4][]", description="The curve's heading at each (x, y, z, w)"),
        Attribute("rotateXYZ", "vectord[3][]", description="The headings as rotateXYZ angles (degrees)"),
    ),
)


def compute(db):
    if not db.inputs.curve:
        db.error("inputs:curve is empty: give the curve's points")
    polyline = closed_polyline(db.inputs.curve)
    forward, up = axis(db.inputs.forwardAxis), axis(db.inputs.upAxis)
    found = [locate(polyline, d, forward, up) for d in db.inputs.distance]
    db.outputs.location = tuple(f[0] for f in found)
    db.outputs.orientation = tuple(f[1] for f in found)
    db.outputs.rotateXYZ = tuple(f[2] for f in found)
