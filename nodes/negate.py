"""omni.graph.nodes.Negate: the input times -1."""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._math import compute_unary

SPEC = NodeSpec(
    id="omni.graph.nodes.Negate",
    version=1,
    description="outputs:output = -input, elementwise over tuples and arrays.",
    categories=("math:operator",),
    ui_name="Negate",
    inputs=(
        Attribute("input", "any", description="Scalars, vectors or arrays of them"),
    ),
    outputs=(
        Attribute("output", "any", description="Each value times -1"),
    ),
)


def compute(db):
    compute_unary(db, lambda x: -x, "input", "output")
