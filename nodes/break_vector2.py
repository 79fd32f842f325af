"""omni.graph.nodes.BreakVector2: split a 2-vector into x, y."""
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.BreakVector2",
    version=1,
    description="Splits a double[2] tuple into outputs x, y.",
    categories=("math:conversion",),
    ui_name="Break 2-Vector",
    inputs=(
        Attribute("tuple", "double[2]", default=(0.0, 0.0), description="The vector"),
    ),
    outputs=(
        Attribute("x", "double", description="X component"),
        Attribute("y", "double", description="Y component"),
    ),
)


def compute(db):
    db.outputs.x, db.outputs.y = (float(v) for v in db.inputs.tuple)
