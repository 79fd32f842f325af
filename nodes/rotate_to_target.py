"""omni.graph.nodes.RotateToTarget: turn a prim to another prim's orientation, over time (a latent maneuver)."""
from graphflow.spec import NodeSpec
from graphflow_nodes._animation import (
    ELAPSED,
    EXEC_IN,
    EXPONENT,
    FINISHED,
    LAST_FRAME,
    MANEUVER,
    SOURCE_PRIM,
    SOURCE_PRIM_PATH,
    SPEED,
    STOP,
    TARGET_PRIM,
    TARGET_PRIM_PATH,
    USE_SOURCE_PATH,
    USE_TARGET_PATH,
    run_maneuver,
    source_prim,
    target_goal,
)

SPEC = NodeSpec(
    id="omni.graph.nodes.RotateToTarget",
    version=2,
    compatible_versions=(1,),
    description=("On execIn, rotates the source prim (sourcePrimPath when useSourcePath, else sourcePrim) to the target prim's orientation (targetPrimPath when useTargetPath, else targetPrim) along the shortest arc; its position and scale stay. The goal is read when execIn fires: the target prim's world pose expressed in the source's parent frame, so the source ends where the target is in the world. " + MANEUVER),
    categories=("sceneGraph",),
    ui_name="Rotate To Target",
    inputs=(
        EXEC_IN,
        EXPONENT,
        SOURCE_PRIM,
        SOURCE_PRIM_PATH,
        SPEED,
        STOP,
        TARGET_PRIM,
        TARGET_PRIM_PATH,
        USE_SOURCE_PATH,
        USE_TARGET_PATH,
    ),
    outputs=(
        FINISHED,
    ),
    state=(
        ELAPSED,
        LAST_FRAME,
    ),
)


def _goal(db, start):
    return start[0], target_goal(db)[1][1], start[2]


def compute(db):
    run_maneuver(db, source_prim, _goal)
