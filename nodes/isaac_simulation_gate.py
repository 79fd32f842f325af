"""isaacsim.core.nodes.IsaacSimulationGate: pass every step-th execution while the simulation plays.

A graphflow graph only ticks while its world runs, so the gate is open; step
counts pulses as Isaac's node does: the step-th, 2 step-th ... pass, and 0
passes none.
"""
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState

SPEC = NodeSpec(
    id="isaacsim.core.nodes.IsaacSimulationGate",
    version=1,
    aliases=("omni.isaac.core_nodes.IsaacSimulationGate",),
    description=(
        "Passes execIn to execOut on every step-th pulse (step 1: every pulse; step 0: none); "
        "graphflow graphs only tick while the simulation plays."),
    categories=("isaacCore",),
    ui_name="Isaac Simulation Gate",
    inputs=(
        Attribute("execIn", "execution", description="The pulse to gate"),
        Attribute("step", "uint", default=1, description="Pulses per passed pulse (0: none pass)"),
    ),
    outputs=(
        Attribute("execOut", "execution", description="Fires on every step-th pulse"),
    ),
    state=(
        Attribute("pulses", "uint64", default=0, description="Pulses since the last one passed"),
    ),
)


def compute(db):
    if db.inputs.execIn != ExecState.ENABLED:
        return
    step = db.inputs.step
    if step == 0:
        return
    db.state.pulses += 1
    if db.state.pulses >= step:
        db.state.pulses = 0
        db.outputs.execOut = ExecState.ENABLED
