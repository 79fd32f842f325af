"""omni.graph.nodes.ReadPrimLocalTransform: a prim's transform relative to its parent, as a 4x4 matrix."""
from graphflow.spec import Attribute, NodeSpec
from graphflow.world import WorldError
from graphflow_nodes._vectors import matrix_multiply, pose_matrix, rigid_inverse

SPEC = NodeSpec(
    id="omni.graph.nodes.ReadPrimLocalTransform",
    version=1,
    description=(
        "outputs:value = the prim's local transform (its world matrix in its parent's frame), from the "
        "world's current poses; a prim whose parent is the stage root has its world matrix."),
    categories=("sceneGraph",),
    ui_name="Read Prim Local Transform",
    inputs=(
        Attribute("prim", "target", description="The prim to read"),
    ),
    outputs=(
        Attribute("value", "matrixd[16]", description="The local transform matrix"),
    ),
)


def compute(db):
    if not db.inputs.prim:
        db.error("inputs:prim is not set")
    path = db.inputs.prim[0]
    parent = path.rsplit("/", 1)[0]
    try:
        world_matrix = pose_matrix(*db.world.prim_pose(path))
        if not parent:
            db.outputs.value = world_matrix
            return
        parent_matrix = pose_matrix(*db.world.prim_pose(parent))
    except WorldError as error:
        db.error(f"{path}: {error}")
    db.outputs.value = matrix_multiply(world_matrix, rigid_inverse(parent_matrix))
