"""omni.graph.nodes.ScaleToSize: scale a prim to a size over time (a latent maneuver)."""
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
)

SPEC = NodeSpec(
    id="omni.graph.nodes.ScaleToSize",
    version=2,
    compatible_versions=(1,),
    description=('On execIn, scales the prim (primPath when usePath, else prim) from its scale to target (its xformOp:scale, per axis, linearly); position and rotation stay. A simulated body cannot be rescaled (PyBullet keeps its collision shapes): the run fails naming the node and the prim. ' + MANEUVER),
    categories=("sceneGraph",),
    ui_name="Scale To Size",
    inputs=(
        EXEC_IN,
        EXPONENT,
        PRIM,
        PRIM_PATH,
        SPEED,
        STOP,
        Attribute("target", "vectord[3]", default=(0.0, 0.0, 0.0), description="The goal scale, local"),
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
    run_maneuver(db, prim_path, lambda db, start: (start[0], start[1], tuple(float(c) for c in db.inputs.target)))
