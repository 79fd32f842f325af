"""omni.graph.action.ExitApplication: end the run, as Kit's node exits the application."""
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState

SPEC = NodeSpec(
    id="omni.graph.action.ExitApplication",
    version=1,
    description=(
        "An execIn pulse ends the run after the current tick, as Kit's node exits the application "
        "(graphflow run then exits 0, like graphflow.StopRun)."),
    categories=("graph:action", "flowControl"),
    ui_name="Exit Application",
    inputs=(Attribute("execIn", "execution", description="Exit after this tick"),),
)


def compute(db):
    if db.inputs.execIn == ExecState.ENABLED:
        db.request_stop()
