"""omni.graph.nodes.GetPrimLocalToWorldTransform: a prim's world transform, as a 4x4 matrix."""
from graphflow.spec import Attribute, NodeSpec
from graphflow.world import WorldError
from graphflow_nodes._vectors import pose_matrix

SPEC = NodeSpec(
    id="omni.graph.nodes.GetPrimLocalToWorldTransform",
    version=2,
    compatible_versions=(1,),
    description=(
        "outputs:localToWorldTransform = the USD 4x4 matrix taking the prim's local frame to the world, from "
        "the world's current pose of the prim (bodies move with the simulation). The prim is primPath when "
        "usePath is true, else the prim input."),
    categories=("sceneGraph",),
    ui_name="Get Prim Local to World Transform",
    inputs=(
        Attribute("prim", "target", description="The prim (used when usePath is false)"),
        Attribute("primPath", "token", default="", description="The prim's path (used when usePath is true)"),
        Attribute("usePath", "bool", default=True, description="Read primPath instead of prim"),
    ),
    outputs=(
        Attribute("localToWorldTransform", "matrixd[16]", description="Local-to-world matrix"),
    ),
)


def compute(db):
    inputs = db.inputs
    path = inputs.primPath if inputs.usePath else (inputs.prim[0] if inputs.prim else "")
    if not path:
        db.error("no prim: set inputs:primPath (usePath true) or inputs:prim (usePath false)")
    try:
        position, orientation = db.world.prim_pose(path)
    except WorldError as error:
        db.error(f"{path}: {error}")
    db.outputs.localToWorldTransform = pose_matrix(position, orientation)
