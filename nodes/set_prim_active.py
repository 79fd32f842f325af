"""omni.graph.action.SetPrimActive: take a prim out of the simulation, or put it back.

Through the world (``World.set_prim_active``): the free rigid bodies under the
prim stop simulating (no motion, no contacts, rays pass through them) and
resume at rest where they were when activated again; IsPrimActive reads the
change. An articulation link, a kinematic or static body or a jointed body
fails the run with one line naming it (graphflow's world cannot take those out
while running). Every prim is active again when a run restarts.
"""
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState
from graphflow.world import WorldError

SPEC = NodeSpec(
    id="omni.graph.action.SetPrimActive",
    version=2,
    compatible_versions=(1,),
    description=(
        "On execIn, makes the prim (primTarget, else the path in prim) active or inactive and fires execOut. "
        "Inactive, its free rigid bodies leave the simulation (still, without contacts, invisible to rays); "
        "active again, they resume at rest. Articulation links, kinematic, static and jointed bodies fail the "
        "run."),
    categories=("graph:action", "sceneGraph"),
    ui_name="Set Prim Active",
    inputs=(
        Attribute("active", "bool", default=False, description="Whether to set the prim active or not"),
        Attribute("execIn", "execution", description="Set the prim's activity"),
        Attribute("prim", "path", default="", description="The prim to be (de)activated (when primTarget is unset)"),
        Attribute("primTarget", "target", optional=True, description="The prim to be (de)activated"),
    ),
    outputs=(
        Attribute("execOut", "execution", description="Fires after the prim was (de)activated"),
    ),
)


def compute(db):
    if db.inputs.execIn != ExecState.ENABLED:
        return
    path = db.inputs.primTarget[0] if db.inputs.primTarget else db.inputs.prim
    if not path:
        db.error("no prim: set inputs:primTarget or inputs:prim")
    try:
        db.world.set_prim_active(path, bool(db.inputs.active))
    except WorldError as error:
        db.error(f"{path}: {error}" if path not in str(error) else str(error))
    db.outputs.execOut = ExecState.ENABLED
