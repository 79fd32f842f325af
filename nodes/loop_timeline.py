"""omni.graph.nodes.LoopTimeline: switch the timeline's looping flag."""
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState
from graphflow_nodes._timeline import timeline

SPEC = NodeSpec(
    id="omni.graph.nodes.LoopTimeline",
    version=1,
    description=(
        "On execIn, records whether playback loops (GetTimeline's isLooping reads it) and fires execOut. The "
        "run's clock keeps moving forward: graphflow does not wrap time at the end of the play range."),
    categories=("time",),
    ui_name="Set playback looping",
    inputs=(
        Attribute("execIn", "execution", description="Set the flag"),
        Attribute("loop", "bool", default=False, description="Loop playback"),
    ),
    outputs=(Attribute("execOut", "execution", description="Fires after"),),
)


def compute(db):
    if db.inputs.execIn != ExecState.ENABLED:
        return
    timeline(db).looping = bool(db.inputs.loop)
    db.outputs.execOut = ExecState.ENABLED
