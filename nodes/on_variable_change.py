"""omni.graph.action.OnVariableChange: fire when a graph variable's value changes.

The node looks at the variable once a tick (as every event source computes):
a change made by a node later in the tick fires on the next tick. The value it
first sees after a reset is the starting point, not a change.
"""
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState

SPEC = NodeSpec(
    id="omni.graph.action.OnVariableChange",
    version=2,
    compatible_versions=(1,),
    description=(
        "Event source. 'changed' fires on a tick when the graph variable variableName holds a different value "
        "than on the previous tick."),
    categories=("graph:action", "event"),
    ui_name="On Variable Change",
    inputs=(
        Attribute("variableName", "token", default="", description="The graph variable to watch"),
        Attribute("onlyPlayback", "bool", default=True,
                  description="Only compute while playing (graphflow always plays while running)"),
    ),
    outputs=(
        Attribute("changed", "execution", description="Fires when the value changed"),
    ),
)


def compute(db):
    name = db.inputs.variableName
    if not name:
        db.error("inputs:variableName is empty; name the graph variable to watch")
    value = db.get_variable(name)
    if "seen" in db.internal and db.internal["seen"] != value:
        db.outputs.changed = ExecState.ENABLED
    db.internal["seen"] = value
