"""graphflow.StopRun: ends the run when pulsed, so a graph can say it is done."""
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState

SPEC = NodeSpec(
    id="graphflow.StopRun",
    version=1,
    description=(
        "An execIn pulse asks the runtime to stop after the current tick "
        "(graphflow run then exits 0). Fires execOut so a final log line can follow."),
    categories=("graph:action", "flowControl"),
    ui_name="Stop Run",
    inputs=(Attribute("execIn", "execution", description="Stop after this tick"),),
    outputs=(Attribute("execOut", "execution", description="Fires after the stop was requested"),),
)


def compute(db):
    if db.inputs.execIn == ExecState.ENABLED:
        db.request_stop()
        db.outputs.execOut = ExecState.ENABLED
