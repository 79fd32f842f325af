"""isaacsim.asset.gen.conveyor.IsaacConveyor: a belt that carries what lies on it.

Isaac gives the conveyor's rigid body a PhysX surface velocity; PyBullet has
none, so on every onStep the node sets, for each free body touching the belt,
its velocity component along the belt direction (direction in the conveyor's
frame) to ``velocity`` m/s, leaving the other components to the physics.
Friction acts during the step after that, so a box slips a little behind
the belt (about 10 % at 0.2 m/s with PyBullet's default friction), where
PhysX's surface velocity has it keep pace.
Bodies that are links of an articulation are left alone. Texture animation
inputs are accepted and have no effect headless.
"""
import math

from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState
from graphflow.world import WorldError

from ._ros2 import rotate_into

SPEC = NodeSpec(
    id="isaacsim.asset.gen.conveyor.IsaacConveyor",
    version=1,
    aliases=("omni.isaac.conveyor.IsaacConveyor",),
    description=(
        "On onStep, moves the free bodies touching conveyorPrim at 'velocity' m/s along 'direction' "
        "(conveyor frame) when enabled."),
    categories=("isaacConveyor",),
    ui_name="Conveyor Belt",
    inputs=(
        Attribute("onStep", "execution", description="Apply the belt for this step"),
        Attribute("conveyorPrim", "target", description="The conveyor's rigid body"),
        Attribute("enabled", "bool", default=True, description="The belt runs"),
        Attribute("velocity", "float", default=0.0, description="Belt speed, m/s"),
        Attribute("direction", "float[3]", default=(1.0, 0.0, 0.0), description="Belt direction in the conveyor frame"),
        Attribute("curved", "bool", default=False, description="Curved belt (not modelled: treated as straight)"),
        Attribute("delta", "float", default=0.0, description="Step length (unused: the world's time step is used)"),
        Attribute("animateTexture", "bool", default=False, description="Animate the belt texture (no renderer: no effect)"),
        Attribute("animateDirection", "float[2]", default=(1.0, 0.0), description="Texture direction (no effect)"),
        Attribute("animateScale", "float", default=1.0, description="Texture speed scale (no effect)"),
    ),
)


def compute(db):
    if db.inputs.onStep != ExecState.ENABLED or not db.inputs.enabled:
        return
    if not db.inputs.conveyorPrim:
        db.error("inputs:conveyorPrim is not set: no conveyor")
    if db.inputs.curved:
        db.error("inputs:curved: curved conveyors are not modelled")
    path = db.inputs.conveyorPrim[0]
    length = math.sqrt(sum(c * c for c in db.inputs.direction))
    if length == 0:
        db.error("inputs:direction is zero")
    try:
        orientation = db.world.prim_pose(path)[1]
        inverse = (-orientation[0], -orientation[1], -orientation[2], orientation[3])
        axis = rotate_into(inverse, tuple(c / length for c in db.inputs.direction))
        carried = sorted({contact[0] for contact in db.world.contacts(path) if contact[0]})
    except WorldError as error:
        db.error(f"inputs:conveyorPrim: {error}")
    for other in carried:
        try:
            velocity = db.world.prim_velocity(other)[0]
            along = sum(v * a for v, a in zip(velocity, axis))
            wanted = tuple(v + (db.inputs.velocity - along) * a for v, a in zip(velocity, axis))
            db.world.set_attribute(other, "physics:velocity", wanted)
        except WorldError:
            continue   # a link of an articulation, or a static body: the belt does not move it
