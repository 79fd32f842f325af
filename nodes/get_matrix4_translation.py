"""omni.graph.nodes.GetMatrix4Translation: the translation of a 4x4 transform."""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._vectors import matrix_translation

SPEC = NodeSpec(
    id="omni.graph.nodes.GetMatrix4Translation",
    version=1,
    description="outputs:translation = the translation of matrix, a USD 4x4 transform (its last row).",
    categories=("math:operator",),
    ui_name="Get Translation",
    inputs=(
        Attribute("matrix", "matrixd[16]", default=(1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0,
                                                   0.0, 0.0, 0.0, 1.0), description="The transformation matrix"),
    ),
    outputs=(
        Attribute("translation", "vectord[3]", description="The translation"),
    ),
)


def compute(db):
    db.outputs.translation = matrix_translation(db.inputs.matrix)
