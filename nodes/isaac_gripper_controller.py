"""isaacsim.robot.manipulators.IsaacGripperController: open, close or stop a finger gripper.

The node keeps a position target per gripper joint: ``open`` sets it to
openPosition, ``close`` to closePosition, ``stop`` to where the joints are
now. On every pulse it outputs the joint names and position commands, moved
toward the target by at most gripperSpeed x time step per joint when speeds
are given (one speed for all, or one per joint). Connect the outputs to an
ArticulationController. Joints are jointNames (default: every joint of
articulationRootPrim).
"""
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState

SPEC = NodeSpec(
    id="isaacsim.robot.manipulators.IsaacGripperController",
    version=1,
    aliases=("omni.isaac.manipulators.IsaacGripperController",),
    description=(
        "open / close / stop set the finger joints' target (openPosition, closePosition, or where they are); "
        "every pulse outputs jointNames and positionCommands toward it, at gripperSpeed (m/s or rad/s) when given."),
    categories=("isaacManipulators",),
    ui_name="Gripper Controller",
    inputs=(
        Attribute("execIn", "execution", description="Output the commands"),
        Attribute("open", "execution", description="Open the gripper"),
        Attribute("close", "execution", description="Close the gripper"),
        Attribute("stop", "execution", description="Hold the joints where they are"),
        Attribute("articulationRootPrim", "target", description="The robot's articulation root"),
        Attribute("gripperPrim", "target", optional=True, description="The gripper (informational)"),
        Attribute("jointNames", "token[]", description="Gripper joints (default: all joints of the articulation)"),
        Attribute("openPosition", "double[]", description="Joint positions when open (one per joint)"),
        Attribute("closePosition", "double[]", description="Joint positions when closed (one per joint)"),
        Attribute("gripperSpeed", "double[]", description="Joint speed limits (one, or one per joint; empty: jump)"),
    ),
    outputs=(
        Attribute("execOut", "execution", description="Fires after the commands were computed"),
        Attribute("jointNames", "token[]", description="The gripper joints"),
        Attribute("positionCommands", "double[]", description="Position commands for the joints"),
    ),
)


def compute(db):
    inputs = db.inputs
    if not inputs.articulationRootPrim:
        db.error("inputs:articulationRootPrim is not set: no gripper to command")
    path = inputs.articulationRootPrim[0]
    names = list(db.world.joint_names(path))
    joints = list(inputs.jointNames) or names
    missing = [name for name in joints if name not in names]
    if missing:
        db.error(f"inputs:jointNames: {path} has no joint {', '.join(missing)}")
    current = db.world.joint_positions(path)
    now = [current[names.index(name)] for name in joints]
    for pin, attribute in (("close", "closePosition"), ("open", "openPosition")):
        if getattr(inputs, pin) == ExecState.ENABLED:
            target = list(getattr(inputs, attribute))
            if len(target) != len(joints):
                db.error(f"inputs:{attribute} has {len(target)} values for {len(joints)} joints")
            db.internal["target"] = target
            break
    else:
        if inputs.stop == ExecState.ENABLED:
            db.internal["target"] = now
    target = db.internal.get("target")
    if target is None:
        return
    commands = db.internal.get("command", now)
    speeds = list(inputs.gripperSpeed)
    if speeds:
        if len(speeds) == 1:
            speeds = speeds * len(joints)
        if len(speeds) != len(joints):
            db.error(f"inputs:gripperSpeed has {len(speeds)} values for {len(joints)} joints")
        step = [speed * db.time_step for speed in speeds]
        commands = [c + max(-s, min(s, t - c)) for c, t, s in zip(commands, target, step)]
    else:
        commands = list(target)
    db.internal["command"] = commands
    db.outputs.jointNames = tuple(joints)
    db.outputs.positionCommands = tuple(commands)
    db.outputs.execOut = ExecState.ENABLED
