"""omni.graph.core.WriteVariable: set a graph variable when pulsed."""
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState, TypeMismatch

SPEC = NodeSpec(
    id="omni.graph.core.WriteVariable",
    version=2,
    compatible_versions=(1,),
    description=(
        "On an execIn pulse, sets the graph variable named by variableName to "
        "'value' (converted to the variable's type), passes the stored value through on"
        " outputs:value and fires execOut. An unset value or one that does not fit the"
        " variable's type is a run-time error."),
    categories=("graph:action", "variables"),
    ui_name="Write Variable",
    inputs=(
        Attribute("execIn", "execution", description="Input execution"),
        Attribute("variableName", "token", default="", description="Name of the graph variable"),
        Attribute("value", "any", description="The new value"),
        Attribute("graph", "target", optional=True,
                  description="Ignored, as in Kit since version 2: the variable is this graph's"),
        Attribute("targetPath", "token", default="", description="Ignored, as in Kit since version 2"),
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
    value = db.inputs.value
    if value is None:
        db.error("inputs:value has no value; connect it or set a value")
        return
    try:
        db.set_variable(name, value)
    except TypeMismatch as error:
        db.error(f"inputs:value does not fit graph variable {name!r}: {error}")
        return
    db.outputs.value = db.get_variable(name)  # as stored (coerced to the variable's type)
    db.outputs.execOut = ExecState.ENABLED
