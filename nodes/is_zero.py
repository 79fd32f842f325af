"""omni.graph.nodes.IsZero: whether every component of a value is within tolerance of zero."""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._math import is_number, plain

SPEC = NodeSpec(
    id="omni.graph.nodes.IsZero",
    version=1,
    description="outputs:result = every number in value (a scalar, tuple, matrix or array) has |x| <= tolerance.",
    categories=("math:condition",),
    ui_name="Is Zero",
    inputs=(
        Attribute("value", "any", description="Value(s) to check"),
        Attribute("tolerance", "double", default=0.0, description="How close to 0 counts as zero"),
    ),
    outputs=(
        Attribute("result", "bool", description="All are zero"),
    ),
)


def _numbers(value):
    if isinstance(value, tuple):
        for item in value:
            yield from _numbers(item)
    else:
        yield value


def compute(db):
    values = list(_numbers(plain(db.inputs.value)))
    if not all(is_number(v) for v in values):
        db.error(f"inputs:value must hold numbers, got {db.inputs.value!r}")
    db.outputs.result = all(abs(v) <= db.inputs.tolerance for v in values)
