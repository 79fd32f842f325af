"""omni.graph.action.SyncGate: fire once every wired execIn has arrived with the same sync value."""
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState

SPEC = NodeSpec(
    id="omni.graph.action.SyncGate",
    version=2,
    compatible_versions=(1,),
    description=(
        "Counts execIn pulses that arrive with the same syncValue; a new syncValue restarts the count. When "
        "the count reaches the number of exec outputs wired into execIn, execOut fires (once per sync value). "
        "outputs:syncValue always carries the latest syncValue, whether execOut fired or not."),
    categories=("graph:action", "flowControl"),
    ui_name="Sync Gate",
    inputs=(
        Attribute("execIn", "execution", description="One of the signals to wait for"),
        Attribute("syncValue", "uint64", default=0, description="The value each signal is checked against"),
    ),
    outputs=(
        Attribute("execOut", "execution", description="Fires when every wired signal arrived at one sync value"),
        Attribute("syncValue", "uint64", description="The current sync value"),
    ),
    state=(
        Attribute("count", "int", default=0, description="Signals seen at the current sync value"),
        Attribute("value", "uint64", default=0, description="The current sync value"),
    ),
)


def compute(db):
    if db.inputs.execIn != ExecState.ENABLED:
        return
    value = db.inputs.syncValue
    if value != db.state.value:
        db.state.value = value
        db.state.count = 0
    db.state.count += 1
    db.outputs.syncValue = value
    if db.state.count == max(db.exec_input_sources("execIn"), 1):
        db.outputs.execOut = ExecState.ENABLED
