"""omni.graph.nodes.Absolute: absolute values, elementwise over vectors and arrays."""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._math import compute_unary

SPEC = NodeSpec(
    id="omni.graph.nodes.Absolute",
    version=1,
    description="outputs:absolute = |input| for each scalar of a scalar, vector, or array of them.",
    categories=("math:operator",),
    ui_name="Absolute",
    inputs=(
        Attribute("input", "any", description="Scalar(s) or vector(s)"),
    ),
    outputs=(
        Attribute("absolute", "any", description="The absolute value(s), same shape"),
    ),
)


def compute(db):
    compute_unary(db, abs, "input", "absolute")
