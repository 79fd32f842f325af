"""omni.graph.nodes.BooleanNot: logical not, elementwise."""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._math import MathError, elementwise, is_boolean

SPEC = NodeSpec(
    id="omni.graph.nodes.BooleanNot",
    version=1,
    description="outputs:valueOut = not valueIn, for a bool or elementwise for a bool array.",
    categories=("math:condition",),
    ui_name="Boolean Not",
    inputs=(
        Attribute("valueIn", "any", default=False, description="bool or bool[]"),
    ),
    outputs=(
        Attribute("valueOut", "any", description="bool, or bool[] for arrays"),
    ),
)


def compute(db):
    try:
        db.outputs.valueOut = elementwise(lambda x: not x, [db.inputs.valueIn], ("valueIn",),
                                          is_boolean, "bools")
    except MathError as error:
        db.error(str(error))
