"""omni.graph.action.OnLoaded: fire once, on the graph's first update after it is loaded (or reset)."""
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState

SPEC = NodeSpec(
    id="omni.graph.action.OnLoaded",
    version=1,
    description="Event source. execOut fires once, on the first tick after the graph is loaded or reset.",
    categories=("graph:action", "event"),
    ui_name="On Loaded",
    outputs=(
        Attribute("execOut", "execution", description="Fires on the first tick"),
    ),
    state=(
        Attribute("fired", "bool", default=False, description="execOut has fired"),
    ),
)


def compute(db):
    if not db.state.fired:
        db.state.fired = True
        db.outputs.execOut = ExecState.ENABLED
