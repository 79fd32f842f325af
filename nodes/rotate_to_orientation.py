"""omni.graph.nodes.RotateToOrientation: rotate a prim to an orientation given as XYZ Euler angles, over time (a latent maneuver)."""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._animation import (
    ELAPSED,
    EXEC_IN,
    EXPONENT,
    FINISHED,
    LAST_FRAME,
    MANEUVER,
    PRIM,
    PRIM_PATH,
    SPEED,
    STOP,
    USE_PATH,
    euler_xyz_quaternion,
    prim_path,
    run_maneuver,
)

SPEC = NodeSpec(
    id="omni.graph.nodes.RotateToOrientation",
    version=2,
    compatible_versions=(1,),
    description=("On execIn, rotates the prim (primPath when usePath, else prim) from its orientation to target, Euler angles in degrees applied as USD's rotateXYZ (about X, then Y, then Z) in its parent's frame, along the shortest arc; position and scale stay. " + MANEUVER),
    categories=("sceneGraph",),
    ui_name="Rotate To Orientation",
    inputs=(
        EXEC_IN,
        EXPONENT,
        PRIM,
        PRIM_PATH,
        SPEED,
        STOP,
        Attribute("target", "vectord[3]", default=(0.0, 0.0, 0.0),
                  description="The goal orientation, XYZ Euler angles in degrees, local"),
        USE_PATH,
    ),
    outputs=(
        FINISHED,
    ),
    state=(
        ELAPSED,
        LAST_FRAME,
    ),
)


def compute(db):
    run_maneuver(db, prim_path, lambda db, start: (start[0], euler_xyz_quaternion(db.inputs.target), start[2]))
