"""omni.graph.nodes.EachZero: which elements of a value are zero, within a tolerance."""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._math import plain, zero_flags

SPEC = NodeSpec(
    id="omni.graph.nodes.EachZero",
    version=1,
    description=(
        "outputs:result = one bool per element of value, true where the element is zero (an element that is itself a tuple or vector is zero when all its numbers are): [3, 0, 1] -> [false, true, false]; a scalar gives one bool. Zero means |x| <= tolerance."),
    categories=("math:condition",),
    ui_name="Each Zero",
    inputs=(
        Attribute("tolerance", "double", default=0.0, description="How close to 0 counts as zero"),
        Attribute("value", "any", description="Value(s) to check"),
    ),
    outputs=(
        Attribute("result", "any", description="Whether the elements are zero"),
    ),
)


def compute(db):
    zeros = zero_flags(db)
    db.outputs.result = zeros if isinstance(plain(db.inputs.value), tuple) else zeros[0]
