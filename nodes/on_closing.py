"""omni.graph.action.OnClosing: fire once when the run ends.

Kit fires it while the stage closes. A graphflow run's stage closes when the
run ends, so execOut fires once after the last tick (the tick limit, the time
limit or a StopRun), with the world as the last step left it and no further
physics step; downstream nodes compute as on any tick (a print, a ROS 2
publish, a variable write the checks read). A run that fails does not fire it.
A --trace file records ticks, so the closing pass is not in it; its log lines
print as usual.
"""
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState

SPEC = NodeSpec(
    id="omni.graph.action.OnClosing",
    version=1,
    description=(
        "Event source. execOut fires once when the run ends, after its last tick (tick or time limit, or a "
        "StopRun), with no further physics step; never on a tick, and not when the run fails."),
    categories=("graph:action", "event"),
    ui_name="On Closing",
    outputs=(
        Attribute("execOut", "execution", description="Fires when the run ends"),
    ),
    fires_at_run_end=True,
)


def compute(db):
    db.outputs.execOut = ExecState.ENABLED
