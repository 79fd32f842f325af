"""omni.graph.nodes.StopTimeline: stop playback, which ends a graphflow run after this tick."""
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState
from graphflow_nodes._timeline import timeline

SPEC = NodeSpec(
    id="omni.graph.nodes.StopTimeline",
    version=1,
    description=(
        "On execIn, stops the timeline at the current time: the run ends normally after this tick (its checks "
        "are judged, as when graphflow.StopRun fires) and GetTimeline reads isPlaying false for the rest of "
        "it. Fires execOut."),
    categories=("time",),
    ui_name="Stop playback",
    inputs=(Attribute("execIn", "execution", description="Stop playback"),),
    outputs=(Attribute("execOut", "execution", description="Fires after the stop was requested"),),
)


def compute(db):
    if db.inputs.execIn != ExecState.ENABLED:
        return
    timeline(db).playing = False
    db.request_stop()
    db.outputs.execOut = ExecState.ENABLED
