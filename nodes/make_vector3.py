"""omni.graph.nodes.MakeVector3: build a double[3] from x, y, z."""
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.MakeVector3",
    version=1,
    description="outputs:tuple = (x, y, z) as a double[3].",
    categories=("math:conversion",),
    ui_name="Make 3-Vector",
    inputs=(
        Attribute("x", "double", default=0.0, description="X component"),
        Attribute("y", "double", default=0.0, description="Y component"),
        Attribute("z", "double", default=0.0, description="Z component"),
    ),
    outputs=(
        Attribute("tuple", "double[3]", description="The vector (x, y, z)"),
    ),
)


def compute(db):
    db.outputs.tuple = (float(db.inputs.x), float(db.inputs.y), float(db.inputs.z))
