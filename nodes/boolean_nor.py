"""omni.graph.nodes.BooleanNor: not (a or b), elementwise."""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._math import compute_binary, is_boolean

SPEC = NodeSpec(
    id="omni.graph.nodes.BooleanNor",
    version=2,
    compatible_versions=(1,),
    description=(
        "outputs:result = not (a or b) for bools, or pairwise for bool arrays of one length (a single bool is "
        "broadcast over an array). Unset inputs read false."),
    categories=("math:condition",),
    ui_name="Boolean NOR",
    inputs=(
        Attribute("a", "any", default=False, description="bool or bool[]"),
        Attribute("b", "any", default=False, description="bool or bool[]"),
    ),
    outputs=(
        Attribute("result", "any", description="bool, or bool[] for arrays"),
    ),
)

def compute(db):
    compute_binary(db, lambda x, y: not (bool(x) or bool(y)), "result", accept=is_boolean, kind="bools")
