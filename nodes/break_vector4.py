"""omni.graph.nodes.BreakVector4: split a 4-vector into x, y, z, w."""
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.BreakVector4",
    version=1,
    description="Splits a 4-component tuple (e.g. a quaternion x, y, z, w) into outputs x, y, z, w.",
    categories=("math:conversion",),
    ui_name="Break 4-Vector",
    inputs=(
        Attribute("tuple", "double[4]", default=(0.0, 0.0, 0.0, 0.0), description="The 4-vector"),
    ),
    outputs=(
        Attribute("x", "double", description="First component"),
        Attribute("y", "double", description="Second component"),
        Attribute("z", "double", description="Third component"),
        Attribute("w", "double", description="Fourth component"),
    ),
)


def compute(db):
    db.outputs.x, db.outputs.y, db.outputs.z, db.outputs.w = (float(v) for v in db.inputs.tuple)
