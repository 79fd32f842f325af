"""omni.graph.nodes.Normalize: a vector scaled to length 1 (the zero vector stays zero)."""
import math

from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._vectors import is_vector

SPEC = NodeSpec(
    id="omni.graph.nodes.Normalize",
    version=1,
    description=(
        "outputs:result = vector / |vector|, for a 2-, 3- or 4-vector or an array of them; a vector of length "
        "zero gives the zero vector, as Kit."),
    categories=("math:operator",),
    ui_name="Normalize",
    inputs=(
        Attribute("vector", "any", description="Vector (or array of vectors) to normalize"),
    ),
    outputs=(
        Attribute("result", "any", description="The unit vector(s)"),
    ),
)


def _unit(vector):
    length = math.sqrt(sum(c * c for c in vector))
    return tuple(0.0 if length == 0.0 else c / length for c in vector)


def compute(db):
    vector = db.inputs.vector
    if is_vector(vector) and len(vector) in (2, 3, 4):
        db.outputs.result = _unit(vector)
    elif isinstance(vector, tuple) and all(is_vector(v) and len(v) in (2, 3, 4) for v in vector):
        db.outputs.result = tuple(_unit(v) for v in vector)
    else:
        db.error(f"inputs:vector must be a 2-, 3- or 4-vector or an array of them, got {vector!r}")
