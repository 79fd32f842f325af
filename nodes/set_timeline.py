"""omni.graph.nodes.SetTimeline: set one of the timeline's properties (range, rate, or the current time)."""
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState
from graphflow_nodes._timeline import timeline

PROPERTIES = ("Frame", "Time", "StartFrame", "StartTime", "EndFrame", "EndTime", "FramesPerSecond")

SPEC = NodeSpec(
    id="omni.graph.nodes.SetTimeline",
    version=1,
    description=(
        "On execIn, sets propName to propValue and fires execOut. StartTime/EndTime (seconds), StartFrame/EndFrame "
        "(frames at the current rate) and FramesPerSecond are recorded for the run and read back by GetTimeline. "
        "Time and Frame seek the playhead: the value is clamped to the play range (clamped says whether it was); "
        "the run's clock is the simulation's and cannot jump, so a seek to the current time (within half a "
        "tick) does nothing and any other seek fails the run, naming the node, the time asked and the time now."),
    categories=("time",),
    ui_name="Set main timeline",
    inputs=(
        Attribute("execIn", "execution", description="Set the property"),
        Attribute("propName", "token", default="Frame", allowed_tokens=PROPERTIES,
                  description="The property to set"),
        Attribute("propValue", "double", default=0.0, description="Its value"),
    ),
    outputs=(
        Attribute("clamped", "bool", description="The frame or time asked was clamped to the play range"),
        Attribute("execOut", "execution", description="Fires after"),
    ),
)


def compute(db):
    if db.inputs.execIn != ExecState.ENABLED:
        return
    playback, name, value = timeline(db), db.inputs.propName, float(db.inputs.propValue)
    clamped = False
    if name in ("Time", "Frame"):
        asked = value if name == "Time" else playback.time_of(value)
        reached = min(max(asked, playback.start_time), playback.end_time)
        clamped = reached != asked
        if abs(reached - playback.time) > db.time_step / 2.0:
            db.error(f"cannot seek the timeline to {reached:g} s: a run's clock is the simulation's, at "
                     f"{playback.time:g} s, and only moves forward one step per tick")
    elif name == "StartTime":
        playback.start_time = value
    elif name == "EndTime":
        playback.end_time = value
    elif name == "StartFrame":
        playback.start_time = playback.time_of(value)
    elif name == "EndFrame":
        playback.end_time = playback.time_of(value)
    elif name == "FramesPerSecond":
        if not value > 0:
            db.error(f"inputs:propValue: FramesPerSecond must be > 0, got {value:g}")
        playback.frames_per_second = value
    else:
        db.error(f"inputs:propName {name!r} is not one of {', '.join(PROPERTIES)}")
    db.outputs.clamped = clamped
    db.outputs.execOut = ExecState.ENABLED
