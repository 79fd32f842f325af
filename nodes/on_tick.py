"""omni.graph.action.OnTick: the per-update event source."""
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState

SPEC = NodeSpec(
    id="omni.graph.action.OnTick",
    version=2,
    compatible_versions=(1,),
    description=(
        "Fires 'tick' on every graph tick, or once every framePeriod + 1 ticks. "
        "deltaSeconds is the simulated time since the previous pulse; time, "
        "timeSinceStart and absoluteSimTime are the simulated seconds since the "
        "last reset; frame is the tick index. graphflow graphs only tick while "
        "running, so isPlaying is always true and onlyPlayback has no effect."),
    categories=("graph:action", "event"),
    ui_name="On Tick",
    inputs=(
        Attribute("framePeriod", "uint", default=0,
                  description="Ticks skipped between pulses (0 = fire on every tick)"),
        Attribute("onlyPlayback", "bool", default=True,
                  description="Only fire while playing (graphflow always plays while running)"),
    ),
    outputs=(
        Attribute("tick", "execution", description="Fires on each (framePeriod-th) tick"),
        Attribute("deltaSeconds", "double", description="Simulated seconds since the previous pulse"),
        Attribute("time", "double", description="Simulated seconds since reset"),
        Attribute("frame", "double", description="Tick index since reset"),
        Attribute("timeSinceStart", "double", description="Simulated seconds since reset"),
        Attribute("absoluteSimTime", "double", description="Accumulated simulated seconds"),
        Attribute("isPlaying", "bool", description="True while the graph runs"),
    ),
    state=(
        Attribute("skip", "int", default=0, description="Ticks still to skip before the next pulse"),
        Attribute("elapsed", "double", default=0.0, description="Seconds accumulated since the last pulse"),
    ),
)


def compute(db):
    db.state.elapsed += db.time_step
    db.outputs.isPlaying = True
    if db.state.skip > 0:
        db.state.skip -= 1
        return
    db.state.skip = int(db.inputs.framePeriod)
    db.outputs.deltaSeconds = db.state.elapsed
    db.state.elapsed = 0.0
    db.outputs.time = float(db.time)
    db.outputs.frame = float(db.frame)
    db.outputs.timeSinceStart = float(db.time)
    db.outputs.absoluteSimTime = float(db.time)
    db.outputs.tick = ExecState.ENABLED
