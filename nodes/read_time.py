"""omni.graph.nodes.ReadTime: the simulated time, as OnPlaybackTick reports it, without firing."""
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.ReadTime",
    version=1,
    description=(
        "The run's time: deltaSeconds the fixed time step, time and absoluteSimTime the simulated seconds "
        "since reset, frame the tick index, isPlaying true while the run goes. timeSinceStart is Kit's wall "
        "time since the application started; headless runs are reproducible, so it is the simulated time too."),
    categories=("time",),
    ui_name="Read Time",
    outputs=(
        Attribute("absoluteSimTime", "double", description="Simulated seconds since reset"),
        Attribute("deltaSeconds", "double", description="Seconds per tick"),
        Attribute("frame", "double", description="Tick index since reset"),
        Attribute("isPlaying", "bool", description="The run is playing (always, while it runs)"),
        Attribute("time", "double", description="Simulated seconds since reset"),
        Attribute("timeSinceStart", "double", description="Simulated seconds since reset"),
    ),
)


def compute(db):
    outputs = db.outputs
    outputs.absoluteSimTime = outputs.time = outputs.timeSinceStart = float(db.time)
    outputs.deltaSeconds = float(db.time_step)
    outputs.frame = float(db.frame)
    outputs.isPlaying = True
