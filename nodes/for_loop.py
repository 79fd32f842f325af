"""omni.graph.action.ForLoop: run loopBody for start, start+step, ... (stop excluded) within one tick."""
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState

SPEC = NodeSpec(
    id="omni.graph.action.ForLoop",
    version=1,
    description=(
        "An execIn pulse runs loopBody once per value start, start+step, ... up to "
        "but excluding stop (counting down when step < 0), all within the same "
        "tick: loopBody is enabled-and-pushed and the node re-enters after its "
        "downstream has finished. outputs:index counts iterations from 0, "
        "outputs:value is the loop value. A breakLoop pulse (from the loop body) "
        "ends the loop after the current iteration. 'finished' fires when the loop "
        "ends, also after a break or when the range is empty. step 0 is an error."),
    categories=("graph:action", "flowControl"),
    ui_name="For Loop",
    inputs=(
        Attribute("execIn", "execution", description="Starts the loop"),
        Attribute("breakLoop", "execution", description="Ends the loop after the current iteration"),
        Attribute("start", "int", default=0, description="First loop value"),
        Attribute("stop", "int", default=0, description="Loop value to stop at (excluded)"),
        Attribute("step", "int", default=1, description="Increment per iteration (not 0)"),
    ),
    outputs=(
        Attribute("loopBody", "execution", description="Fires once per iteration"),
        Attribute("index", "int", description="Iteration number, from 0"),
        Attribute("value", "int", description="Current loop value"),
        Attribute("finished", "execution", description="Fires when the loop ends"),
    ),
    state=(
        Attribute("active", "bool", default=False, description="A loop is running"),
        Attribute("broken", "bool", default=False, description="breakLoop was pulsed"),
        Attribute("i", "int", default=0, description="Iteration number of the current iteration"),
    ),
)


def validate(node_name, values):
    if values.get("step", 1) == 0:
        return ["inputs:step must not be 0 (the loop would never end)"]
    return []


def _iterate(db, i):
    step = db.inputs.step
    if step == 0:
        db.state.active = False
        db.error("inputs:step must not be 0 (the loop would never end)")
        return
    value = db.inputs.start + i * step
    if (step > 0 and value < db.inputs.stop) or (step < 0 and value > db.inputs.stop):
        db.state.active = True
        db.state.i = i
        db.outputs.index = i
        db.outputs.value = value
        db.outputs.loopBody = ExecState.ENABLED_AND_PUSH
    else:
        db.state.active = False
        db.outputs.finished = ExecState.ENABLED


def compute(db):
    if db.inputs.breakLoop == ExecState.ENABLED:
        if db.state.active:
            db.state.broken = True
        return
    if db.inputs.execIn == ExecState.ENABLED:
        db.state.broken = False
        _iterate(db, 0)
    elif db.state.active:  # re-entry after loopBody's downstream finished
        if db.state.broken:
            db.state.active = False
            db.state.broken = False
            db.outputs.finished = ExecState.ENABLED
        else:
            _iterate(db, db.state.i + 1)
