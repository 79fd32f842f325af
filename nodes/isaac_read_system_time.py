"""isaacsim.core.nodes.IsaacReadSystemTime: the run's clock, as a reproducible "system" time.

Isaac reads the host's wall clock. A graphflow run must give the same trace
every time, so the system time here is the run's own clock: seconds of
simulated time since the run started (the epoch is the run's start, not
1970), which is what the wall clock would read in a run paced at real time.
Graphs that stamp messages with it (a ROS 2 publisher's timeStamp) get
increasing, reproducible stamps; a graph that needs the real date cannot get it.
Isaac's referenceTime (numerator / denominator, s) asks for the system time at
a timeline time: on this clock that is the reference time itself.
"""
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="isaacsim.core.nodes.IsaacReadSystemTime",
    version=1,
    aliases=("omni.isaac.core_nodes.IsaacReadSystemTime",),
    description=(
        "outputs:systemTime = seconds since the run started, on the run's simulated clock (reproducible; "
        "epoch = the run's start, not the host's wall clock), or the time at referenceTimeNumerator / "
        "referenceTimeDenominator when a denominator is given. swhFrameNumber (Isaac 4.x) has no effect."),
    categories=("isaacCore",),
    ui_name="Isaac Read System Time",
    inputs=(
        Attribute("referenceTimeNumerator", "int64", default=0, description="Reference time numerator (s)"),
        Attribute("referenceTimeDenominator", "uint64", default=0, description="Reference time denominator (0: now)"),
        Attribute("swhFrameNumber", "int64", default=0, description="Kit's fabric frame number (no effect here)"),
    ),
    outputs=(
        Attribute("systemTime", "double", description="Seconds since the run started"),
    ),
)


def compute(db):
    denominator = db.inputs.referenceTimeDenominator
    db.outputs.systemTime = db.inputs.referenceTimeNumerator / denominator if denominator else float(db.time)
