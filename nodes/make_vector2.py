"""omni.graph.nodes.MakeVector2: build a double[2] from x, y."""
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.MakeVector2",
    version=1,
    description="outputs:tuple = (x, y) as a double[2].",
    categories=("math:conversion",),
    ui_name="Make 2-Vector",
    inputs=(
        Attribute("x", "double", default=0.0, description="X component"),
        Attribute("y", "double", default=0.0, description="Y component"),
    ),
    outputs=(
        Attribute("tuple", "double[2]", description="The vector (x, y)"),
    ),
)


def compute(db):
    db.outputs.tuple = (float(db.inputs.x), float(db.inputs.y))
