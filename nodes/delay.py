"""omni.graph.action.Delay: a latent node that fires 'finished' after some simulated time."""
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState

SPEC = NodeSpec(
    id="omni.graph.action.Delay",
    version=1,
    description=(
        "An execIn pulse starts a latent delay (outputs:finished = LATENT_PUSH); the "
        "executor recomputes the node every tick, and once 'duration' seconds of "
        "simulated time have passed since the pulse 'finished' fires (LATENT_FINISH). "
        "Pulses arriving while the delay runs are ignored (the node is locked). "
        "A duration of 0 fires 'finished' at once."),
    categories=("graph:action", "time"),
    ui_name="Delay",
    inputs=(
        Attribute("execIn", "execution", description="Starts the delay"),
        Attribute("duration", "double", default=0.0, minimum=0.0,
                  description="Simulated seconds to wait"),
    ),
    outputs=(
        Attribute("finished", "execution", description="Fires when the delay has elapsed"),
    ),
    state=(
        Attribute("elapsed", "double", default=0.0, description="Seconds waited so far"),
        Attribute("lastFrame", "int", default=-1, description="Tick whose time step was last counted"),
    ),
)

_EPSILON = 1e-9


def compute(db):
    if db.is_latent:
        if db.inputs.execIn == ExecState.ENABLED:
            return  # locked: pulses during the delay are ignored
        # Count each tick's step once, starting with the tick after the pulse.
        if db.frame != db.state.lastFrame:
            db.state.lastFrame = db.frame
            db.state.elapsed += db.time_step
        if db.state.elapsed + _EPSILON >= db.inputs.duration:
            db.outputs.finished = ExecState.LATENT_FINISH
        return
    if db.inputs.execIn != ExecState.ENABLED:
        return
    duration = db.inputs.duration
    if duration < 0:
        db.error(f"inputs:duration must be >= 0 seconds, got {duration}")
        return
    if duration <= 0:
        db.outputs.finished = ExecState.ENABLED
        return
    db.state.elapsed = 0.0
    db.state.lastFrame = db.frame
    db.outputs.finished = ExecState.LATENT_PUSH
