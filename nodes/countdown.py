"""omni.graph.action.Countdown: pulse every period executions for duration executions, then finish.

As Kit's reference describes it: the execIn pulse that starts the countdown is
execution 0 and fires nothing; executions 1..duration each set tickValue and
alpha = tickValue / duration and fire 'tick' when tickValue is a multiple of
period; the one after the last tick fires 'finished'. A new execIn while
counting restarts it. Later executions are the re-entries the node asks for
(it stays latent until finished).
"""
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState

SPEC = NodeSpec(
    id="omni.graph.action.Countdown",
    version=1,
    description=(
        "An execIn pulse starts a countdown of duration executions (one a tick): every period-th fires "
        "'tick' (with tickValue and alpha = tickValue / duration), and after the last 'finished'. "
        "Duration 10, period 3: ticks after 3, 6 and 9 executions, finished after the 10th."),
    categories=("graph:action", "flowControl"),
    ui_name="Countdown",
    inputs=(
        Attribute("execIn", "execution", description="Starts (or restarts) the countdown"),
        Attribute("duration", "int", default=5, minimum=0, description="Length of the countdown, executions"),
        Attribute("period", "int", default=1, minimum=1, description="Executions between 'tick' pulses"),
    ),
    outputs=(
        Attribute("tick", "execution", description="Fires every period executions"),
        Attribute("finished", "execution", description="Fires once the countdown is over"),
        Attribute("tickValue", "int", description="Executions since the start, in [1, duration]"),
        Attribute("alpha", "float", description="tickValue / duration (0 at the start, 1 when over)"),
    ),
    state=(
        Attribute("count", "int", default=-1, description="Executions since the start (-1: idle)"),
    ),
)


def compute(db):
    inputs, state = db.inputs, db.state
    if inputs.execIn == ExecState.ENABLED:
        state.count = 0
        db.outputs.alpha, db.outputs.tickValue = 0.0, 0
        db.outputs.tick = ExecState.LATENT_PUSH
        return
    if state.count < 0:
        return
    state.count += 1
    if state.count > inputs.duration:
        state.count = -1
        db.outputs.alpha = 1.0
        db.outputs.finished = ExecState.LATENT_FINISH
        return
    db.outputs.tickValue = state.count
    db.outputs.alpha = state.count / inputs.duration
    if state.count % inputs.period == 0:
        db.outputs.tick = ExecState.ENABLED
