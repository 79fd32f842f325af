"""omni.graph.action.OnPlaybackTick: fires on every tick while the timeline plays."""
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState

SPEC = NodeSpec(
    id="omni.graph.action.OnPlaybackTick",
    version=2,
    description=(
        "Fires 'tick' on every graph tick (a running graphflow graph is always "
        "playing). deltaSeconds is the fixed time step, time the simulated seconds "
        "since reset, frame = time x (1 / time step), i.e. the tick index."),
    categories=("graph:action", "event"),
    ui_name="On Playback Tick",
    outputs=(
        Attribute("tick", "execution", description="Fires on every tick"),
        Attribute("deltaSeconds", "double", description="Seconds since the previous tick"),
        Attribute("time", "double", description="Simulated seconds since reset"),
        Attribute("frame", "double", description="Tick index since reset"),
    ),
)


def compute(db):
    db.outputs.deltaSeconds = float(db.time_step)
    db.outputs.time = float(db.time)
    db.outputs.frame = float(db.frame)
    db.outputs.tick = ExecState.ENABLED
