"""omni.graph.nodes.MoveToTransform: move a prim to a local 4x4 transform (translation, rotation, scale) over time."""
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
from graphflow_nodes._vectors import IDENTITY, matrix_quaternion, matrix_translation

SPEC = NodeSpec(
    id="omni.graph.nodes.MoveToTransform",
    version=2,
    compatible_versions=(1,),
    description=("On execIn, moves the prim (primPath when usePath, else prim) from its transform to target, a USD 4x4 matrix in its parent's frame: translation and scale interpolated linearly, rotation along the shortest arc. The matrix is taken as translate, rotate, scale (shear is dropped). " + MANEUVER),
    categories=("sceneGraph",),
    ui_name="Move to Transform",
    inputs=(
        EXEC_IN,
        EXPONENT,
        PRIM,
        PRIM_PATH,
        SPEED,
        STOP,
        Attribute("target", "matrixd[16]", default=IDENTITY, description="The goal transform, local"),
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


def _goal(db, start):
    matrix = db.inputs.target
    scale = tuple(sum(c * c for c in matrix[4 * i:4 * i + 3]) ** 0.5 for i in range(3))
    if min(scale) <= 0.0:
        db.error("inputs:target has a zero scale: no rotation can be taken from it")
    return stage_units(db, matrix_translation(matrix)), matrix_quaternion(matrix), scale


def compute(db):
    run_maneuver(db, prim_path, _goal)
