"""isaacsim.core.nodes.OnPhysicsStep: fires once for every physics step taken since the last tick."""
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState

SPEC = NodeSpec(
    id="isaacsim.core.nodes.OnPhysicsStep",
    version=1,
    aliases=("omni.isaac.core_nodes.OnPhysicsStep",),
    description=(
        "Fires 'step' on a tick when the world has stepped since the previous pulse (not while the "
        "timeline is paused). deltaSimulationTime is the simulated time of those steps (deltaSystemTime "
        "the same: graphflow's system clock is the run's simulated clock), simulationTime the world's "
        "simulated seconds since reset."),
    categories=("graph:action", "event"),
    ui_name="On Physics Step",
    outputs=(
        Attribute("step", "execution", description="Fires after physics stepped"),
        Attribute("deltaSimulationTime", "double", description="Simulated seconds since the previous pulse"),
        Attribute("deltaSystemTime", "double",
                  description="System seconds since the previous pulse (the run's clock: deltaSimulationTime)"),
        Attribute("simulationTime", "double", description="Simulated seconds since reset"),
    ),
    state=(
        Attribute("lastStepIndex", "int", default=0, description="The world's step index at the previous pulse"),
    ),
)


def compute(db):
    step_index = db.world.step_index
    if step_index == db.state.lastStepIndex:
        return
    db.outputs.deltaSimulationTime = (step_index - db.state.lastStepIndex) * db.world.time_step
    db.outputs.deltaSystemTime = db.outputs.deltaSimulationTime
    db.outputs.simulationTime = float(db.world.time)
    db.state.lastStepIndex = step_index
    db.outputs.step = ExecState.ENABLED
