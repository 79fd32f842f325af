"""omni.graph.nodes.GetTimeline: the main timeline's time, play range, rate and flags."""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._timeline import timeline

SPEC = NodeSpec(
    id="omni.graph.nodes.GetTimeline",
    version=1,
    description=(
        "The run's timeline: time is the simulated seconds since reset (a run's clock is the simulation's) and "
        "frame = time x framesPerSecond; the play range and rate are the stage's startTimeCode, endTimeCode and "
        "timeCodesPerSecond (USD's fallbacks 0, 0, 24) unless SetTimeline changed them; isLooping as LoopTimeline "
        "set it (false at first); isPlaying is true while the run goes, false after StopTimeline."),
    categories=("time",),
    ui_name="Get main timeline",
    outputs=(
        Attribute("endFrame", "double", description="End of the play range, frames"),
        Attribute("endTime", "double", description="End of the play range, seconds"),
        Attribute("frame", "double", description="The current frame"),
        Attribute("framesPerSecond", "double", description="Frames (time codes) per second"),
        Attribute("isLooping", "bool", description="Playback loops"),
        Attribute("isPlaying", "bool", description="The timeline plays"),
        Attribute("startFrame", "double", description="Start of the play range, frames"),
        Attribute("startTime", "double", description="Start of the play range, seconds"),
        Attribute("time", "double", description="The current time, seconds"),
    ),
)


def compute(db):
    playback, outputs = timeline(db), db.outputs
    outputs.time = playback.time
    outputs.frame = playback.frame_of(playback.time)
    outputs.startTime, outputs.startFrame = playback.start_time, playback.frame_of(playback.start_time)
    outputs.endTime, outputs.endFrame = playback.end_time, playback.frame_of(playback.end_time)
    outputs.framesPerSecond = playback.frames_per_second
    outputs.isLooping = playback.looping
    outputs.isPlaying = playback.playing
