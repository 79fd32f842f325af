"""omni.graph.nodes.GetPrimDirectionVector: a prim's up, forward and right directions in the world."""
import math

from graphflow.spec import Attribute, NodeSpec
from graphflow.world import WorldError
from graphflow_nodes._vectors import pose_matrix

SPEC = NodeSpec(
    id="omni.graph.nodes.GetPrimDirectionVector",
    version=2,
    description=(
        "The prim's local axes in the world, from the world's current pose of the prim, unit length: right = "
        "+X, up = +Y, forward = -Z (Kit's omni.graph.nodes convention, as its look-at matrix states), and "
        "left, down, backward their opposites. The prim is primPath when usePath is true, else the prim input."),
    categories=("sceneGraph",),
    ui_name="Get Prim Direction Vector",
    inputs=(
        Attribute("prim", "target", description="The prim (used when usePath is false)"),
        Attribute("primPath", "token", default="", description="The prim's path (used when usePath is true)"),
        Attribute("usePath", "bool", default=True, description="Read primPath instead of prim"),
    ),
    outputs=(
        Attribute("backwardVector", "double[3]", description="The prim's +Z in the world"),
        Attribute("downVector", "double[3]", description="The prim's -Y in the world"),
        Attribute("forwardVector", "double[3]", description="The prim's -Z in the world"),
        Attribute("leftVector", "double[3]", description="The prim's -X in the world"),
        Attribute("rightVector", "double[3]", description="The prim's +X in the world"),
        Attribute("upVector", "double[3]", description="The prim's +Y in the world"),
    ),
)


def _unit(row):
    length = math.sqrt(sum(c * c for c in row)) or 1.0
    return tuple(c / length for c in row)


def compute(db):
    inputs = db.inputs
    path = inputs.primPath if inputs.usePath else (inputs.prim[0] if inputs.prim else "")
    if not path:
        db.error("no prim: set inputs:primPath (usePath true) or inputs:prim (usePath false)")
    try:
        matrix = pose_matrix(*db.world.prim_pose(path))
    except WorldError as error:
        db.error(f"{path}: {error}")
    right, up, back = (_unit(matrix[4 * i:4 * i + 3]) for i in range(3))
    outputs = db.outputs
    outputs.rightVector, outputs.upVector, outputs.backwardVector = right, up, back
    outputs.leftVector, outputs.downVector, outputs.forwardVector = (tuple(-c for c in v) for v in (right, up, back))
