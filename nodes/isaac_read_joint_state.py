"""isaacsim.sensors.physics.IsaacReadJointState: an articulation's whole joint state in one reading."""
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState
from graphflow.world import WorldError

SPEC = NodeSpec(
    id="isaacsim.sensors.physics.IsaacReadJointState",
    version=1,
    description=(
        "On execIn, the movable joints of the articulation at prim in DOF order: names, positions (rad or m), "
        "velocities (rad/s or m/s), the efforts their actuation applied in the last step (N m or N) and DOF "
        "types (0 revolute, 1 prismatic). graphflow's world reports SI units whatever the stage's units, so "
        "stageMetersPerUnit is 1."),
    categories=("isaacPhysicsSensor",),
    ui_name="Isaac Read Joint State Node",
    inputs=(
        Attribute("execIn", "execution", description="Read the state"),
        Attribute("prim", "target", description="The articulation root"),
    ),
    outputs=(
        Attribute("execOut", "execution", description="Fires after the reading"),
        Attribute("sensorTime", "float", default=0.0, description="Simulated time of the reading, s"),
        Attribute("jointNames", "token[]", description="Joint names in DOF order"),
        Attribute("jointPositions", "double[]", description="Joint positions, rad or m"),
        Attribute("jointVelocities", "double[]", description="Joint velocities, rad/s or m/s"),
        Attribute("jointEfforts", "double[]", description="Joint efforts, N m or N"),
        Attribute("jointDofTypes", "uchar[]", description="0 = revolute, 1 = prismatic, per DOF"),
        Attribute("stageMetersPerUnit", "float", default=0.0, description="1: the values are SI already"),
    ),
)


def compute(db):
    if db.inputs.execIn != ExecState.ENABLED:
        return
    if not db.inputs.prim:
        db.error("inputs:prim is not set: no articulation to read")
    path, world = db.inputs.prim[0], db.world
    try:
        db.outputs.jointNames = tuple(world.joint_names(path))
        db.outputs.jointPositions = tuple(float(q) for q in world.joint_positions(path))
        db.outputs.jointVelocities = tuple(float(v) for v in world.joint_velocities(path))
        db.outputs.jointEfforts = tuple(float(e) for e in world.joint_efforts(path))
        db.outputs.jointDofTypes = tuple(int(kind) for kind in world.joint_dof_types(path))
    except WorldError as error:
        db.error(f"inputs:prim: {error}")
    db.outputs.stageMetersPerUnit = 1.0
    db.outputs.sensorTime = float(db.time)
    db.outputs.execOut = ExecState.ENABLED
