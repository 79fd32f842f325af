"""isaacsim.core.nodes.OgnIsaacRunOneSimulationFrame: pass the first pulse only.

Isaac uses it to run its downstream once, on the first frame of the play
(sensor helpers that set up their publishers once).
"""
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState

SPEC = NodeSpec(
    id="isaacsim.core.nodes.OgnIsaacRunOneSimulationFrame",
    version=1,
    aliases=("omni.isaac.core_nodes.OgnIsaacRunOneSimulationFrame",),
    description="Fires step on the first execIn after a reset and never again until the next reset.",
    categories=("isaacCore",),
    ui_name="Run One Simulation Frame",
    inputs=(
        Attribute("execIn", "execution", description="The input execution"),
    ),
    outputs=(
        Attribute("step", "execution", description="Fires once"),
    ),
    state=(
        Attribute("done", "bool", default=False, description="The pulse has been passed on"),
    ),
)


def compute(db):
    if db.inputs.execIn == ExecState.ENABLED and not db.state.done:
        db.state.done = True
        db.outputs.step = ExecState.ENABLED
