"""omni.graph.nodes.BooleanXor: a xor b, elementwise."""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._math import compute_binary, is_boolean

SPEC = NodeSpec(
    id="omni.graph.nodes.BooleanXor",
    version=1,
    description=(
        "outputs:result = a xor b for bools, or pairwise for bool arrays of one length (a single bool is "
        "broadcast over an array). Unset inputs read false."),
    categories=("math:condition",),
    ui_name="Boolean XOR",
    inputs=(
        Attribute("a", "any", default=False, description="bool or bool[]"),
        Attribute("b", "any", default=False, description="bool or bool[]"),
    ),
    outputs=(
        Attribute("result", "any", description="bool, or bool[] for arrays"),
    ),
)

def compute(db):
    compute_binary(db, lambda x, y: bool(x) != bool(y), "result", accept=is_boolean, kind="bools")
