"""graphflow.ReadPrimPose: the world pose of a prim, live from physics."""
from graphflow.spec import Attribute, NodeSpec
from graphflow.world import WorldError

SPEC = NodeSpec(
    id="graphflow.ReadPrimPose",
    version=1,
    description=(
        "World position (m) and orientation (quaternion x, y, z, w) of a prim: a rigid body, a collider, "
        "a joint (its body0-side frame) or any prim carried by a body (e.g. an end-effector frame)."),
    categories=("sceneGraph",),
    ui_name="Read Prim Pose",
    inputs=(
        Attribute("prim", "target", description="The prim whose pose to read"),
    ),
    outputs=(
        Attribute("position", "double[3]", description="World position, m"),
        Attribute("orientation", "quatd[4]", description="World orientation (x, y, z, w)"),
    ),
)


def compute(db):
    if not db.inputs.prim:
        db.error("no prim given")
    try:
        position, orientation = db.world.prim_pose(db.inputs.prim[0])
    except WorldError as error:
        db.error(str(error))
    db.outputs.position = tuple(float(c) for c in position)
    db.outputs.orientation = tuple(float(c) for c in orientation)
