"""omni.graph.nodes.Increment: value + increment, elementwise, keeping value's type.

As Kit's node, an integer value stays an integer: the sum is chopped toward
zero (4 + 3.2 -> 7).
"""
import math

from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._math import MathError, elementwise

SPEC = NodeSpec(
    id="omni.graph.nodes.Increment",
    version=1,
    description=(
        "outputs:result = value + increment, for numbers, tuples and arrays elementwise; the result keeps "
        "value's type and shape (an integer value is chopped: 4 + 3.2 -> 7)."),
    categories=("math:operator",),
    ui_name="Increment",
    inputs=(
        Attribute("value", "any", description="The operand to increase"),
        Attribute("increment", "double", default=1.0, description="Amount added to every element"),
    ),
    outputs=(
        Attribute("result", "any", description="value + increment"),
    ),
)


def compute(db):
    if db.inputs.value is None:
        db.error("inputs:value has no value; connect it or set a value")
    amount = db.inputs.increment

    def add(element):
        total = element + amount
        return math.trunc(total) if isinstance(element, int) else total
    try:
        db.outputs.result = elementwise(add, [db.inputs.value], ("value",))
    except MathError as error:
        db.error(str(error))
