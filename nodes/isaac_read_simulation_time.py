"""isaacsim.core.nodes.IsaacReadSimulationTime: simulated seconds since the world was reset.

Isaac's referenceTime (numerator / denominator, seconds) asks for the
simulation time at a given timeline time; a graphflow run plays its timeline
from 0 at one fixed step, so that is the reference time itself.
``resetOnStop`` is always true here: a reset world starts again at 0.
"""
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="isaacsim.core.nodes.IsaacReadSimulationTime",
    version=1,
    aliases=("omni.isaac.core_nodes.IsaacReadSimulationTime",),
    description=(
        "Outputs the simulated time in seconds since reset (after this tick's physics step), or the "
        "simulation time at referenceTimeNumerator / referenceTimeDenominator when a denominator is given."),
    categories=("isaacCore",),
    ui_name="Isaac Read Simulation Time",
    inputs=(
        Attribute("referenceTimeNumerator", "int64", default=0, description="Reference time numerator (s)"),
        Attribute("referenceTimeDenominator", "uint64", default=0, description="Reference time denominator (0: now)"),
        Attribute("resetOnStop", "bool", default=True, description="Time restarts at 0 when the world resets"),
    ),
    outputs=(
        Attribute("simulationTime", "double", description="Simulated seconds"),
    ),
)


def compute(db):
    denominator = db.inputs.referenceTimeDenominator
    if denominator:
        db.outputs.simulationTime = db.inputs.referenceTimeNumerator / denominator
    else:
        db.outputs.simulationTime = float(db.time)
