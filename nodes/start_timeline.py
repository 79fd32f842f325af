"""omni.graph.nodes.StartTimeline: start playback (a running graphflow run already plays)."""
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState
from graphflow_nodes._timeline import timeline

SPEC = NodeSpec(
    id="omni.graph.nodes.StartTimeline",
    version=1,
    description=(
        "On execIn, fires execOut. The timeline plays while a run goes, so there is nothing to start; a "
        "StopTimeline earlier in the same tick still ends the run after it."),
    categories=("time",),
    ui_name="Start playback",
    inputs=(Attribute("execIn", "execution", description="Start playback"),),
    outputs=(Attribute("execOut", "execution", description="Fires after"),),
)


def compute(db):
    if db.inputs.execIn != ExecState.ENABLED:
        return
    timeline(db)
    db.outputs.execOut = ExecState.ENABLED
