"""isaacsim.core.nodes.IsaacTimeSplitter: seconds as whole seconds plus the fraction in ms, us and ns.

As Isaac's node: the time in whole nanoseconds (truncated toward zero), split
into whole seconds rounded down and the remaining nanoseconds, shown also as
milliseconds and microseconds (rounded down); so -1.25 s is -2 s and 750 ms.
"""
import math

from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="isaacsim.core.nodes.IsaacTimeSplitter",
    version=1,
    aliases=("omni.isaac.core_nodes.IsaacTimeSplitter",),
    description=(
        "Splits time (s) into whole seconds (floor) and the remaining fraction as milliseconds [0, 1e3), "
        "microseconds [0, 1e6) and nanoseconds [0, 1e9)."),
    categories=("isaacCore",),
    ui_name="Isaac Time Splitter",
    inputs=(
        Attribute("time", "double", default=0.0, description="Time, s"),
    ),
    outputs=(
        Attribute("seconds", "int", description="Whole seconds"),
        Attribute("milliseconds", "uint", description="Fraction of a second, ms"),
        Attribute("microseconds", "uint", description="Fraction of a second, us"),
        Attribute("nanoseconds", "uint", description="Fraction of a second, ns"),
    ),
)


def compute(db):
    time = db.inputs.time
    if not math.isfinite(time):
        db.error(f"inputs:time is {time}, not a finite number of seconds")
    seconds, nanoseconds = divmod(int(time * 1e9), 1_000_000_000)
    db.outputs.seconds = seconds
    db.outputs.nanoseconds = nanoseconds
    db.outputs.microseconds = nanoseconds // 1000
    db.outputs.milliseconds = nanoseconds // 1_000_000
