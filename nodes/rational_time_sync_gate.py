"""omni.graph.action.RationalTimeSyncGate: SyncGate whose sync value is a rational time."""
import math

from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState

SPEC = NodeSpec(
    id="omni.graph.action.RationalTimeSyncGate",
    version=1,
    description=(
        "Counts execIn pulses that arrive at the same rational time numerator/denominator (compared reduced "
        "by their greatest common divisor, so 1/2 and 3/6 are the same while 1/0 and 2/0 are not); a new "
        "time restarts the count. When the count reaches the number of exec outputs wired into execIn, "
        "execOut fires. The outputs always carry the latest time."),
    categories=("graph:action", "flowControl"),
    ui_name="Rational Sync Gate",
    inputs=(
        Attribute("execIn", "execution", description="One of the signals to wait for"),
        Attribute("rationalTimeNumerator", "int64", default=0, description="Numerator of the sync time"),
        Attribute("rationalTimeDenominator", "uint64", default=0, description="Denominator of the sync time"),
    ),
    outputs=(
        Attribute("execOut", "execution", description="Fires when every wired signal arrived at one time"),
        Attribute("rationalTimeNumerator", "int64", description="Numerator of the current sync time"),
        Attribute("rationalTimeDenominator", "uint64", description="Denominator of the current sync time"),
    ),
    state=(
        Attribute("count", "int", default=0, description="Signals seen at the current sync time"),
    ),
)


def _reduced(numerator: int, denominator: int) -> tuple[int, int]:
    """The time in lowest terms; a zero denominator stays as authored (Kit does not reduce it)."""
    if denominator == 0:
        return numerator, denominator
    divisor = math.gcd(numerator, denominator)
    return (numerator // divisor, denominator // divisor) if divisor > 1 else (numerator, denominator)


def compute(db):
    if db.inputs.execIn != ExecState.ENABLED:
        return
    numerator, denominator = db.inputs.rationalTimeNumerator, db.inputs.rationalTimeDenominator
    time = _reduced(numerator, denominator)
    if time != db.internal.get("time", (0, 0)):
        db.internal["time"] = time
        db.state.count = 0
    db.state.count += 1
    db.outputs.rationalTimeNumerator, db.outputs.rationalTimeDenominator = numerator, denominator
    if db.state.count == max(db.exec_input_sources("execIn"), 1):
        db.outputs.execOut = ExecState.ENABLED
