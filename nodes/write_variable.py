"""omni.graph.core.WriteVariable: set a graph variable when pulsed."""
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState

SPEC = NodeSpec(
    id="omni.graph.core.WriteVariable",
    version=2,
    compatible_versions=(1,),
    description=(
        "On an execIn pulse, sets the graph variable named by variableName to "
        "'value', passes the value through on outputs:value and fires execOut."),
    categories=("graph:action", "variables"),
    ui_name="Write Variable",
    inputs=(
        Attribute("execIn", "execution", description="Input execution"),
        Attribute("variableName", "token", default="", description="Name of the graph variable"),
        Attribute("value", "any", description="The new value"),
    ),
    outputs=(
        Attribute("execOut", "execution", description="Fires after the variable is written"),
        Attribute("value", "any", description="The value written"),
    ),
)


def compute(db):
    if db.inputs.execIn != ExecState.ENABLED:
        return
    name = db.inputs.variableName
    if not name:
        db.error("inputs:variableName is empty; name the graph variable to write")
        return
    db.set_variable(name, db.inputs.value)
    db.outputs.value = db.inputs.value
    db.outputs.execOut = ExecState.ENABLED
