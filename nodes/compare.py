"""omni.graph.nodes.Compare: compare a and b with an operator token."""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._math import COMPARISONS, MathError, elementwise, is_number, require

SPEC = NodeSpec(
    id="omni.graph.nodes.Compare",
    version=1,
    description=(
        "outputs:result = a <operation> b, with operation one of >, <, >=, <=, ==, !=. "
        "Numbers, tuples and arrays compare elementwise (a scalar is broadcast) and "
        "give a bool per element; two tokens/strings compare as text."),
    categories=("math:condition",),
    ui_name="Compare",
    inputs=(
        Attribute("a", "any", description="Left operand"),
        Attribute("b", "any", description="Right operand"),
        Attribute("operation", "token", default=">", allowed_tokens=tuple(COMPARISONS),
                  description="The comparison: >, <, >=, <=, == or !="),
    ),
    outputs=(
        Attribute("result", "any", description="bool, or a tuple of bools for tuples and arrays"),
    ),
)


def compute(db):
    operation = COMPARISONS.get(db.inputs.operation)
    if operation is None:
        db.error(f"inputs:operation must be one of {', '.join(COMPARISONS)}, got {db.inputs.operation!r}")
        return
    try:
        a, b = require(db, "a"), require(db, "b")
        if isinstance(a, str) and isinstance(b, str):
            db.outputs.result = bool(operation(a, b))
            return
        db.outputs.result = elementwise(lambda x, y: bool(operation(x, y)), [a, b], ("a", "b"),
                                        is_number, "numbers (or two strings)")
    except MathError as error:
        db.error(str(error))
