"""omni.graph.nodes.ToDouble: a bool or number (or a tuple or array of them) as doubles.

Key and button states are bools; the math nodes take numbers only, so a graph
that scales a held key into a motion (the keyboard gantry) converts it here.
"""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._math import MathError, elementwise, is_boolean, is_number

SPEC = NodeSpec(
    id="omni.graph.nodes.ToDouble",
    version=1,
    description=(
        "outputs:converted = value as 64-bit floats: true -> 1.0, false -> 0.0, numbers unchanged "
        "in value; tuples and arrays elementwise, keeping their shape."),
    categories=("math:conversion",),
    ui_name="To Double",
    inputs=(
        Attribute("value", "any", description="bool, number, or a tuple or array of them"),
    ),
    outputs=(
        Attribute("converted", "any", description="double, or doubles in the input's shape"),
    ),
)


# exact types float() converts as they are: no shape to keep, nothing to check (a key state, every tick)
_SCALARS = frozenset((bool, int, float))


def compute(db):
    value = db.inputs.value
    if type(value) in _SCALARS:
        db.outputs.converted = float(value)
        return
    if value is None:
        db.error("inputs:value has no value; connect it or set a value")
    try:
        db.outputs.converted = elementwise(float, [value], ("value",),
                                           lambda x: is_boolean(x) or is_number(x), "bools or numbers")
    except MathError as error:
        db.error(str(error))
