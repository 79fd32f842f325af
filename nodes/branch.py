"""omni.graph.action.Branch: route an execution pulse by a boolean condition."""
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState

SPEC = NodeSpec(
    id="omni.graph.action.Branch",
    version=1,
    description="Routes an execution pulse to execTrue or execFalse by a boolean condition.",
    categories=("graph:action", "flowControl"),
    ui_name="Branch",
    inputs=(
        Attribute("execIn", "execution", description="Input execution"),
        Attribute("condition", "bool", default=False, description="The boolean condition"),
    ),
    outputs=(
        Attribute("execTrue", "execution", description="Fires when the condition is true"),
        Attribute("execFalse", "execution", description="Fires when the condition is false"),
    ),
)


def compute(db):
    if db.inputs.condition:
        db.outputs.execTrue = ExecState.ENABLED
    else:
        db.outputs.execFalse = ExecState.ENABLED
