"""omni.graph.nodes.MakeTransformLookAt: the view matrix of a camera at center looking at eye.

Kit's node passes its inputs to Gf's SetLookAt swapped, as
``SetLookAt(center, eye, up)``: the result is the world-to-camera (view) matrix
of a camera standing at ``center`` and looking toward ``eye``, with the camera
looking down its -Z axis, +Y up and +X right (Kit's description: "forward is
-Z, computed from eye - center"). Row vectors, as USD: ``p_world * M`` is the
point in the camera's frame, so ``center`` maps to the origin and ``eye`` to
(0, 0, -|eye - center|). Its inverse is the camera's world transform.
"""
import math

from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.MakeTransformLookAt",
    version=1,
    description=(
        "outputs:transform = the world-to-camera (view) matrix of a camera at center looking toward eye, "
        "-Z forward, +Y up (as Kit: Gf's SetLookAt(center, eye, up)); USD row vectors, so center maps to "
        "the origin and eye onto the -Z axis."),
    categories=("math:operator",),
    ui_name="Make Transformation Matrix Look At",
    inputs=(
        Attribute("center", "vectord[3]", default=(0.0, 0.0, 0.0),
                  description="The position of the center or target-position in world-space"),
        Attribute("eye", "vectord[3]", default=(1.0, 0.0, 0.0),
                  description="The position of the eye, or from-position in world-space"),
        Attribute("up", "vectord[3]", default=(0.0, 1.0, 0.0), description="The direction of the up vector"),
    ),
    outputs=(
        Attribute("transform", "matrixd[16]", description="The view matrix"),
    ),
)


def compute(db):
    center, eye, up = db.inputs.center, db.inputs.eye, db.inputs.up
    forward = _unit([e - c for e, c in zip(eye, center)])
    if forward is None:
        db.error("inputs:eye and inputs:center are the same point: no direction to look along")
    side = _unit(_cross(forward, up))
    if side is None:
        db.error("inputs:up is parallel to eye - center (or zero): the camera's roll is undefined")
    true_up = _cross(side, forward)
    columns = (side, true_up, tuple(-f for f in forward))
    rotation = tuple(columns[j][i] for i in range(3) for j in range(3))
    translation = tuple(-sum(c * axis for c, axis in zip(center, column)) for column in columns)
    db.outputs.transform = (*rotation[0:3], 0.0, *rotation[3:6], 0.0, *rotation[6:9], 0.0, *translation, 1.0)


def _cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def _unit(v):
    norm = math.sqrt(sum(c * c for c in v))
    return tuple(c / norm for c in v) if norm > 1e-12 else None
