"""isaacsim.core.nodes.IsaacArticulationState: joint names, positions and velocities of an articulation.

Joints are chosen by jointNames, else jointIndices, else all, in the
articulation's DOF order. measuredJointEfforts is what each joint's
actuation applied in the last step; Isaac also reports joint reaction forces
and torques, which graphflow's world does not measure, so those two outputs
stay empty.
"""
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState
from graphflow.world import WorldError

SPEC = NodeSpec(
    id="isaacsim.core.nodes.IsaacArticulationState",
    version=1,
    aliases=("omni.isaac.core_nodes.IsaacArticulationState",),
    description=(
        "On execIn, the names, positions (rad or m), velocities (rad/s or m/s) and applied efforts (N m or N) "
        "of the chosen joints of the articulation at robotPath (or targetPrim). The measured reaction forces "
        "and torques stay empty: graphflow's world does not measure joint reactions."),
    categories=("isaacCore",),
    ui_name="Articulation State",
    inputs=(
        Attribute("execIn", "execution", description="Read the state"),
        Attribute("targetPrim", "target", description="The articulation root (used when robotPath is empty)"),
        Attribute("robotPath", "string", default="", description="Articulation root path; overrides targetPrim"),
        Attribute("jointNames", "token[]", description="Joints to read by name (empty: jointIndices, else all)"),
        Attribute("jointIndices", "int[]", description="Joints to read by DOF index"),
    ),
    outputs=(
        Attribute("execOut", "execution", description="Fires after the state was read"),
        Attribute("jointNames", "token[]", description="The joints read"),
        Attribute("jointPositions", "double[]", description="Their positions, rad or m"),
        Attribute("jointVelocities", "double[]", description="Their velocities, rad/s or m/s"),
        Attribute("measuredJointEfforts", "double[]", description="Efforts their actuation applied, N m or N"),
        Attribute("measuredJointForces", "double[3][]", description="Empty: not measured by graphflow's world"),
        Attribute("measuredJointTorques", "double[3][]", description="Empty: not measured by graphflow's world"),
    ),
)


def compute(db):
    if db.inputs.execIn != ExecState.ENABLED:
        return
    inputs = db.inputs
    path = inputs.robotPath or (inputs.targetPrim[0] if inputs.targetPrim else "")
    if not path:
        db.error("no robot prim: set inputs:robotPath or inputs:targetPrim")
    try:
        names = db.world.joint_names(path)
        positions, velocities = db.world.joint_positions(path), db.world.joint_velocities(path)
        efforts = db.world.joint_efforts(path)
    except WorldError as error:
        db.error(str(error))
    if inputs.jointNames:
        unknown = [name for name in inputs.jointNames if name not in names]
        if unknown:
            db.error(f"inputs:jointNames: {path} has no joint {', '.join(unknown)} (its joints: {', '.join(names)})")
        indices = [names.index(name) for name in inputs.jointNames]
    elif inputs.jointIndices:
        indices = list(inputs.jointIndices)
        if any(not 0 <= i < len(names) for i in indices):
            db.error(f"inputs:jointIndices: {path} has {len(names)} joints (indices 0..{len(names) - 1})")
    else:
        indices = list(range(len(names)))
    db.outputs.jointNames = tuple(names[i] for i in indices)
    db.outputs.jointPositions = tuple(float(positions[i]) for i in indices)
    db.outputs.jointVelocities = tuple(float(velocities[i]) for i in indices)
    db.outputs.measuredJointEfforts = tuple(float(efforts[i]) for i in indices)
    db.outputs.execOut = ExecState.ENABLED
