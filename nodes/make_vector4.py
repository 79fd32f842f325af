"""omni.graph.nodes.MakeVector4: four numbers as one 4-vector."""
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.MakeVector4",
    version=1,
    description="outputs:tuple = (x, y, z, w) as a double[4] (e.g. a quaternion in x, y, z, w order).",
    categories=("math:conversion",),
    ui_name="Make 4-Vector",
    inputs=(
        Attribute("x", "double", default=0.0, description="First component"),
        Attribute("y", "double", default=0.0, description="Second component"),
        Attribute("z", "double", default=0.0, description="Third component"),
        Attribute("w", "double", default=0.0, description="Fourth component"),
    ),
    outputs=(
        Attribute("tuple", "double[4]", description="(x, y, z, w)"),
    ),
)


def compute(db):
    inputs = db.inputs
    db.outputs.tuple = (float(inputs.x), float(inputs.y), float(inputs.z), float(inputs.w))
