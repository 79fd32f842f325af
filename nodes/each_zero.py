"""omni.graph.nodes.EachZero: which elements of a value are zero, within a tolerance."""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._math import is_number, plain

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


def _zero(db, element) -> bool:
    if isinstance(element, tuple):
        return all(_zero(db, item) for item in element)
    if not is_number(element):
        db.error(f"inputs:value must hold numbers, got {element!r}")
    return abs(element) <= db.inputs.tolerance


def compute(db):
    value = plain(db.inputs.value)
    if value is None:
        db.error("inputs:value has no value; connect it or set a value")
    zeros = tuple(_zero(db, item) for item in value) if isinstance(value, tuple) else (_zero(db, value),)
    db.outputs.result = zeros if isinstance(value, tuple) else zeros[0]
