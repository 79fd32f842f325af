"""omni.graph.nodes.WritePrimLocalTransform: place a prim by its local 4x4 transform."""
import math

from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState
from graphflow.world import WorldError
from graphflow_nodes._vectors import IDENTITY, matrix_quaternion, matrix_translation

SPEC = NodeSpec(
    id="omni.graph.nodes.WritePrimLocalTransform",
    version=1,
    description=(
        "On execIn, sets the prim's transform relative to its parent to value (a USD 4x4 matrix) and fires "
        "execOut. graphflow's world places bodies (a free body or an articulation root is teleported, as "
        "writing its xformOp:translate and xformOp:orient does); a matrix with scale or shear is refused, "
        "the world keeps a body's size."),
    categories=("sceneGraph",),
    ui_name="Write Prim Local Transform",
    inputs=(
        Attribute("execIn", "execution", description="Write the transform"),
        Attribute("prim", "target", description="The prim to write to"),
        Attribute("value", "matrixd[16]", default=IDENTITY, description="The local transform matrix"),
    ),
    outputs=(
        Attribute("execOut", "execution", description="Fires after writing"),
    ),
)


def _rigid(matrix) -> bool:
    """Whether the upper 3x3 is a rotation (orthonormal rows) and the last column (0, 0, 0, 1)."""
    rows = [matrix[4 * i:4 * i + 3] for i in range(3)]
    for i in range(3):
        for j in range(3):
            dot = sum(a * b for a, b in zip(rows[i], rows[j]))
            if not math.isclose(dot, 1.0 if i == j else 0.0, abs_tol=1e-6):
                return False
    return all(math.isclose(matrix[4 * i + 3], 0.0, abs_tol=1e-12) for i in range(3)) and matrix[15] == 1.0


def compute(db):
    if db.inputs.execIn != ExecState.ENABLED:
        return
    if not db.inputs.prim:
        db.error("inputs:prim is not set: no prim to place")
    path, matrix = db.inputs.prim[0], db.inputs.value
    if not _rigid(matrix):
        db.error("inputs:value has scale or shear: graphflow's world places bodies, it does not resize them")
    try:
        db.world.set_attribute(path, "xformOp:translate", matrix_translation(matrix))
        db.world.set_attribute(path, "xformOp:orient", matrix_quaternion(matrix))
    except WorldError as error:
        db.error(f"inputs:prim: {path}: {error}")
    db.outputs.execOut = ExecState.ENABLED
