"""omni.graph.nodes.SetMatrix4Translation: a 4x4 transform with its translation replaced."""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._vectors import IDENTITY

SPEC = NodeSpec(
    id="omni.graph.nodes.SetMatrix4Translation",
    version=1,
    description="outputs:matrix = matrix with its last row's first three values set to translation; rows 0-2 kept.",
    categories=("math:operator",),
    ui_name="Set Translation",
    inputs=(
        Attribute("matrix", "matrixd[16]", default=IDENTITY, description="The matrix to be modified"),
        Attribute("translation", "vectord[3]", default=(0.0, 0.0, 0.0), description="The new translation"),
    ),
    outputs=(
        Attribute("matrix", "matrixd[16]", description="The updated matrix"),
    ),
)


def compute(db):
    t = db.inputs.translation
    db.outputs.matrix = tuple(db.inputs.matrix[:12]) + (float(t[0]), float(t[1]), float(t[2]), db.inputs.matrix[15])
