"""omni.graph.nodes.BreakVector3: split a 3-vector into x, y, z."""
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.BreakVector3",
    version=1,
    description="Splits a double[3] tuple into outputs x, y, z.",
    categories=("math:conversion",),
    ui_name="Break 3-Vector",
    inputs=(
        Attribute("tuple", "double[3]", default=(0.0, 0.0, 0.0), description="The vector"),
    ),
    outputs=(
        Attribute("x", "double", description="X component"),
        Attribute("y", "double", description="Y component"),
        Attribute("z", "double", description="Z component"),
    ),
)


def compute(db):
    value = db.inputs.tuple
    if len(value) != 3:
        db.error(f"inputs:tuple must have 3 components, got {len(value)}")
        return
    db.outputs.x, db.outputs.y, db.outputs.z = (float(v) for v in value)
