"""omni.graph.nodes.CrossProduct: a x b for 3-vectors (or arrays of them, row by row)."""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._vectors import is_vector

SPEC = NodeSpec(
    id="omni.graph.nodes.CrossProduct",
    version=1,
    description="outputs:product = a x b, perpendicular to both 3-vectors; arrays of vectors row by row.",
    categories=("math:operator",),
    ui_name="Cross Product",
    inputs=(
        Attribute("a", "any", description="The first 3-vector (or array of them)"),
        Attribute("b", "any", description="The second 3-vector (or array of them)"),
    ),
    outputs=(
        Attribute("product", "any", description="a x b"),
    ),
)


def _cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def _vector3(value) -> bool:
    return is_vector(value) and len(value) == 3


def compute(db):
    a, b = db.inputs.a, db.inputs.b
    if _vector3(a) and _vector3(b):
        db.outputs.product = _cross(a, b)
    elif (isinstance(a, tuple) and isinstance(b, tuple) and len(a) == len(b)
          and all(_vector3(x) and _vector3(y) for x, y in zip(a, b))):
        db.outputs.product = tuple(_cross(x, y) for x, y in zip(a, b))
    else:
        db.error(f"inputs:a and inputs:b must both be 3-vectors or equally long arrays of them, got {a!r}, {b!r}")
