"""isaacsim.core.nodes.IsaacArticulationController: joint commands to an articulation.

Differences from Isaac, on purpose: a bad command is a run-time error naming
the node (Isaac logs and returns False), ``jointIndices = [0]`` selects joint 0
(Isaac's ``np.any`` test ignores it), and ``execOut`` fires after the commands
were applied so a chain can continue.
"""
import math

from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState

COMMANDS = (("positionCommand", "positions"), ("velocityCommand", "velocities"), ("effortCommand", "efforts"))

SPEC = NodeSpec(
    id="isaacsim.core.nodes.IsaacArticulationController",
    version=1,
    aliases=("omni.isaac.core_nodes.IsaacArticulationController",),
    description=(
        "On execIn, sends position, velocity and effort commands to the joints of "
        "the articulation at robotPath (or targetPrim when robotPath is empty). "
        "Joints are chosen by jointNames, else jointIndices, else all DOFs in order. "
        "Each non-empty command must have one value per chosen joint; NaN leaves "
        "that joint's command unchanged. Values are radians and metres (per second, "
        "N or N m for efforts). A wrong length or an unknown joint is a run-time "
        "error and no command is applied."),
    categories=("isaacCore",),
    ui_name="Articulation Controller",
    inputs=(
        Attribute("execIn", "execution", description="Apply the commands"),
        Attribute("targetPrim", "target", optional=True, description="The articulation root (used when robotPath is empty)"),
        Attribute("robotPath", "string", default="", description="Articulation root path; overrides targetPrim"),
        Attribute("jointNames", "token[]", description="Joints to command, by name"),
        Attribute("jointIndices", "int[]", description="Joints to command, by DOF index (when no names are given)"),
        Attribute("positionCommand", "double[]", description="Position targets (rad or m)"),
        Attribute("velocityCommand", "double[]", description="Velocity targets (rad/s or m/s)"),
        Attribute("effortCommand", "double[]", description="Efforts (N m or N)"),
    ),
    outputs=(
        Attribute("execOut", "execution", description="Fires after the commands were applied"),
    ),
)


def compute(db):
    if db.inputs.execIn != ExecState.ENABLED:
        return
    path = db.inputs.robotPath or (db.inputs.targetPrim[0] if db.inputs.targetPrim else "")
    if not path:
        db.error("no robot prim: set inputs:robotPath or inputs:targetPrim")
    indices = _selected_joints(db, path)
    commands = {}
    for attribute, keyword in COMMANDS:
        values = getattr(db.inputs, attribute)
        if not values:
            continue
        if len(values) != len(indices):
            db.error(f"inputs:{attribute} has {len(values)} values for {len(indices)} joints of {path}; "
                     f"no command applied")
        if any(math.isinf(value) for value in values):
            db.error(f"inputs:{attribute} {list(values)} holds an infinite target; no command applied "
                     f"(targets must be finite; NaN leaves a joint alone)")
        commands[keyword] = [(index, value) for index, value in zip(indices, values) if not math.isnan(value)]
    for keyword, pairs in commands.items():
        if pairs:
            db.world.set_joint_targets(path, [index for index, _ in pairs], **{keyword: [v for _, v in pairs]})
    db.outputs.execOut = ExecState.ENABLED


def validate(node_name, values):
    """Authored commands must be finite (NaN, which leaves a joint alone, is fine); robotPath absolute."""
    problems = [f"inputs:{attribute}: {list(values[attribute])} holds an infinite target (NaN leaves a joint "
                f"alone; infinity is no target)"
                for attribute, _keyword in COMMANDS
                if any(isinstance(v, (int, float)) and math.isinf(v) for v in _floats(values.get(attribute, ())))]
    robot_path = values.get("robotPath", "")
    if isinstance(robot_path, str) and robot_path and not robot_path.startswith("/"):
        problems.append(f"inputs:robotPath: {robot_path!r} is not an absolute prim path (one starts with '/')")
    return problems


def _floats(values):
    for value in values if isinstance(values, (list, tuple)) else ():
        try:
            yield float(value)
        except (TypeError, ValueError):
            continue


def _selected_joints(db, path):
    names = db.world.joint_names(path)
    if db.inputs.jointNames:
        missing = [name for name in db.inputs.jointNames if name not in names]
        if missing:
            db.error(f"inputs:jointNames: {path} has no joint {', '.join(missing)} (joints: {', '.join(names)})")
        return [names.index(name) for name in db.inputs.jointNames]
    if db.inputs.jointIndices:
        bad = [index for index in db.inputs.jointIndices if not 0 <= index < len(names)]
        if bad:
            db.error(f"inputs:jointIndices: {bad} out of range; {path} has {len(names)} joints")
        return list(db.inputs.jointIndices)
    return list(range(len(names)))
