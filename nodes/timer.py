"""omni.graph.nodes.Timer: a value that runs from startValue to endValue over duration seconds."""
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState

SUM_ROUNDING = 1e-9      # s: 30 steps of 1/60 s add up to 0.49999999999999994, which is half a second

SPEC = NodeSpec(
    id="omni.graph.nodes.Timer",
    version=2,
    compatible_versions=(1,),
    description=(
        "A play pulse starts the timer (a latent node): every tick after it, outputs:value = startValue + "
        "(endValue - startValue) * min(elapsed / duration, 1) in simulated seconds and 'updated' fires; once "
        "duration has elapsed 'finished' fires and the timer stops. Play pulses while it runs are ignored. "
        "Version 1's outputs:alpha is version 2's outputs:value."),
    categories=("animation",),
    ui_name="Timer",
    inputs=(
        Attribute("play", "execution", description="Start playing"),
        Attribute("duration", "double", default=1.0, description="Seconds from start to end"),
        Attribute("startValue", "double", default=0.0, description="Value at the start"),
        Attribute("endValue", "double", default=1.0, description="Value at the end"),
    ),
    outputs=(
        Attribute("updated", "execution", description="Fires each tick the value was updated"),
        Attribute("finished", "execution", description="Fires once the duration has elapsed"),
        Attribute("value", "double", default=0.0, description="The current value"),
    ),
    state=(
        Attribute("elapsed", "double", default=0.0, description="Seconds played so far"),
        Attribute("lastFrame", "int", default=-1, description="Tick whose time step was last counted"),
    ),
)


def compute(db):
    inputs = db.inputs
    if not db.is_latent:
        if inputs.play != ExecState.ENABLED:
            return
        db.state.elapsed, db.state.lastFrame = 0.0, db.frame
        db.outputs.value = inputs.startValue
        if inputs.duration <= 0.0:
            db.outputs.value = inputs.endValue
            db.outputs.finished = ExecState.ENABLED
            return
        db.outputs.updated = ExecState.ENABLED
        db.outputs.finished = ExecState.LATENT_PUSH
        return
    if db.frame == db.state.lastFrame:
        return                      # a pulse in the starting tick: one update a tick
    db.state.lastFrame = db.frame
    db.state.elapsed += db.time_step
    progress = min((db.state.elapsed + SUM_ROUNDING) / inputs.duration, 1.0)
    db.outputs.value = inputs.startValue + (inputs.endValue - inputs.startValue) * progress
    db.outputs.updated = ExecState.ENABLED
    if progress >= 1.0:
        db.outputs.finished = ExecState.LATENT_FINISH
