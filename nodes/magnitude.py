"""omni.graph.nodes.Magnitude: the length of a vector (the absolute value of a scalar)."""
import math

from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._math import is_number, plain
from graphflow_nodes._vectors import is_vector

SPEC = NodeSpec(
    id="omni.graph.nodes.Magnitude",
    version=1,
    description=(
        "outputs:magnitude = |input|: a vector's length, a scalar's absolute value, or an array of them for "
        "an array of vectors or scalars."),
    categories=("math:operator",),
    ui_name="Magnitude",
    inputs=(
        Attribute("input", "any", description="Vector(s) or scalar"),
    ),
    outputs=(
        Attribute("magnitude", "any", description="The magnitude(s)"),
    ),
)


def _length(value):
    return abs(value) if is_number(value) else math.sqrt(sum(c * c for c in value))


def compute(db):
    value = plain(db.inputs.input)
    if is_number(value) or is_vector(value) and not isinstance(value[0], tuple):
        db.outputs.magnitude = _length(value)
    elif isinstance(value, tuple) and all(is_number(v) or is_vector(v) for v in value):
        db.outputs.magnitude = tuple(_length(v) for v in value)
    else:
        db.error(f"inputs:input must be a scalar, a vector or an array of them, got {value!r}")
