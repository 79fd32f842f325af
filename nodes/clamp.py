"""omni.graph.nodes.Clamp: limit a value to [lower, upper], elementwise."""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._math import MathError, elementwise, require

SPEC = NodeSpec(
    id="omni.graph.nodes.Clamp",
    version=1,
    description=(
        "outputs:result = input limited to [lower, upper], for numbers, tuples and "
        "arrays, elementwise; scalar bounds are broadcast. lower > upper is a "
        "run-time error."),
    categories=("math:operator",),
    ui_name="Clamp",
    inputs=(
        Attribute("input", "any", description="Value to clamp (number, tuple or array)"),
        Attribute("lower", "any", description="Lower bound"),
        Attribute("upper", "any", description="Upper bound"),
    ),
    outputs=(
        Attribute("result", "any", description="The clamped value"),
    ),
)


def _clamp(value, lower, upper):
    if lower > upper:
        raise MathError(f"inputs:lower ({lower}) is greater than inputs:upper ({upper})")
    return min(max(value, lower), upper)


def compute(db):
    names = ("input", "lower", "upper")
    try:
        db.outputs.result = elementwise(_clamp, [require(db, n) for n in names], names)
    except MathError as error:
        db.error(str(error))
