"""omni.graph.nodes.TranslateToLocation: move a prim to a local position over time (a latent maneuver)."""
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
    prim_path,
    run_maneuver,
    stage_units,
)

SPEC = NodeSpec(
    id="omni.graph.nodes.TranslateToLocation",
    version=2,
    compatible_versions=(1,),
    description=("On execIn, translates the prim (primPath when usePath, else prim) from where it is to target, "
                 "a position in its parent's frame; rotation and scale stay. " + MANEUVER),
    categories=("sceneGraph",),
    ui_name="Translate To Location",
    inputs=(
        EXEC_IN,
        EXPONENT,
        PRIM,
        PRIM_PATH,
        SPEED,
        STOP,
        Attribute("target", "vectord[3]", default=(0.0, 0.0, 0.0), description="The goal position, local"),
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
    run_maneuver(db, prim_path, lambda db, start: (stage_units(db, db.inputs.target), start[1], start[2]))
