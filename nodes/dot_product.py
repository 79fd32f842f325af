"""omni.graph.nodes.DotProduct: a . b for vectors, row by row for arrays of vectors."""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._math import plain
from graphflow_nodes._vectors import is_vector

SPEC = NodeSpec(
    id="omni.graph.nodes.DotProduct",
    version=1,
    description="outputs:product = a . b for two vectors of one size, or row by row for two arrays of them.",
    categories=("math:operator",),
    ui_name="Dot Product",
    inputs=(
        Attribute("a", "any", description="The first vector (or array of vectors)"),
        Attribute("b", "any", description="The second vector (or array of vectors)"),
    ),
    outputs=(
        Attribute("product", "any", description="The dot product(s)"),
    ),
)


def _dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def compute(db):
    a, b = plain(db.inputs.a), plain(db.inputs.b)
    if is_vector(a) and is_vector(b) and len(a) == len(b):
        db.outputs.product = _dot(a, b)
    elif (isinstance(a, tuple) and isinstance(b, tuple) and len(a) == len(b)
          and all(is_vector(x) and is_vector(y) and len(x) == len(y) for x, y in zip(a, b))):
        db.outputs.product = tuple(_dot(x, y) for x, y in zip(a, b))
    else:
        db.error(f"inputs:a and inputs:b must be vectors (or arrays of vectors) of one shape, got {a!r}, {b!r}")
