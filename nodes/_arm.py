"""The arm the pick-and-place controllers drive: any fixed-base chain of revolute joints from the stage's
articulation to its surface gripper's attachment point. Not a node type (the leading underscore keeps the
registry away).

The kinematic chain is read off the stage (graphflow.usd's description): from the body holding the
gripper's attachment joint, up the joint tree to the articulation's root body; each joint's frame in
its parent link, its axis, its limits; the tool frame is the attachment joint's frame, whose +X is the
gripper's forward axis. Where that chain is the UR10's (same joints, same tool poses), ``ur10_chain`` is used
(the published numbers, the stage's to 1e-7 m): the UR10's traces stay bit-identical. A UR10 with another
tool, or converted with another gripper, gets its stage chain.
"""
from __future__ import annotations

from graphflow.poses import Pose, compose, invert, quat_matrix
from graphflow.poses import relative as relative_pose

UR10_JOINT_NAMES = ("shoulder_pan_joint", "shoulder_lift_joint", "elbow_joint",
                    "wrist_1_joint", "wrist_2_joint", "wrist_3_joint")


class Arm:
    """Turns world-frame tool targets into joint position targets for one arm, through the world.

    IK runs on a kinematic copy of the arm (graphflow.kinematics), warm-started from the previous
    solution, so it never touches the simulated state. A target equal to the last one solved keeps its
    solution: solving again from it would return it unchanged.
    """

    def __init__(self, world, robot_path: str, gripper_path: str):
        self.world = world
        self.robot_path = robot_path
        names = world.joint_names(robot_path)
        self.chain, base = arm_chain(world, robot_path, gripper_path, names)
        missing = [name for name in self.chain.names if name not in names]
        if missing:
            raise ValueError(f"{robot_path} does not move the gripper's chain: no joint {', '.join(missing)}")
        self.indices = [names.index(name) for name in self.chain.names]
        self.base_pose = world.prim_pose(base)
        current = world.joint_positions(robot_path)
        self.solution = tuple(current[i] for i in self.indices)
        self._solved_for: tuple | None = None

    def move_tip(self, tip, orientation) -> tuple[float, ...]:
        """Solve IK for the tool point (world frame) and send the joint targets; returns them."""
        target = (tuple(tip), tuple(orientation))
        if target != self._solved_for:
            local_position, local_orientation = relative_pose(self.base_pose, target)
            solution = self.chain.inverse(local_position, local_orientation, self.solution)
            if not solution.converged:
                raise ValueError(f"cannot reach tool target {tuple(round(c, 4) for c in tip)}: "
                                 f"IK left {solution.position_error * 1000:.1f} mm")
            self.solution = solution.positions
            self._solved_for = target
        self.world.set_joint_targets(self.robot_path, self.indices, positions=self.solution)
        return self.solution


def arm_chain(world, robot_path: str, gripper_path: str, names):
    """(chain, path of the prim its base frame is): the stage's, or ``ur10_chain`` where it is the same arm
    (its joints, and the same tool pose from the robot prim to 1 um at test configurations), where the world
    has no stage (the UR10 test worlds) or where the gripper has no attachment frame (the tutorial's legacy
    gripper at the published tool point)."""
    from graphflow.kinematics import ur10_chain

    has_stage = getattr(world, "description", None) is not None or getattr(world, "stage", None) is not None
    if tuple(n for n in names if n in UR10_JOINT_NAMES) != UR10_JOINT_NAMES:
        if not has_stage:
            raise ValueError("this world has no stage to read the arm's joints from")
        return chain_from_stage(world, gripper_path)
    published = ur10_chain()
    try:
        found = chain_from_stage(world, gripper_path) if has_stage else None
    except ValueError:      # no attachment frame to read (the tutorial's legacy gripper): the published tool
        return published, robot_path
    if found is None or _same_tool_poses(world, (published, robot_path), found):
        return published, robot_path
    return found


def _same_tool_poses(world, first, second) -> bool:
    """Whether two (chain, base prim) give the same world tool pose (1 um, 1 urad) at a few configurations."""
    import numpy as np

    if first[0].names != second[0].names:
        return False
    bases = [world.prim_pose(base) for _chain, base in (first, second)]
    for q in np.linspace(-2.5, 2.5, 5)[:, None] * np.linspace(0.3, 1.0, len(first[0].names))[None, :]:
        poses = []
        for (chain, _base), base_pose in zip((first, second), bases):
            tool = chain.forward(q)
            rotation = np.array(quat_matrix(base_pose[1])).reshape(3, 3)
            poses.append((np.array(base_pose[0]) + rotation @ tool[:3, 3], rotation @ tool[:3, :3]))
        if not (np.allclose(poses[0][0], poses[1][0], atol=1e-6) and np.allclose(poses[0][1], poses[1][1], atol=1e-6)):
            return False
    return True


def chain_from_stage(world, gripper_path: str):
    """(SerialChain from the root body to the gripper's attachment frame, the root body's path)."""
    from graphflow.usd.physics_import import load_description

    description = getattr(world, "description", None)
    if description is None:
        description = load_description(world.stage)
    return chain_from_description(description, gripper_path)


def chain_from_description(description, gripper_path: str):
    """The chain of ``chain_from_stage`` from a parsed stage (graphflow.usd.description)."""
    from graphflow.kinematics import Joint, SerialChain

    gripper = next((g for g in description.surface_grippers if g.path == gripper_path), None)
    if gripper is None or not gripper.attachment_points:
        raise ValueError(f"no surface gripper with an attachment point at {gripper_path}")
    attachment = description.joints[gripper.attachment_points[0]]
    parents = {joint.body1: joint for joint in description.joints.values()
               if joint.body0 and joint.body1 and not joint.exclude_from_articulation}
    path, body = [], attachment.body0
    while body in parents:
        path.append(parents[body])
        body = parents[body].body0
    root = body
    joints, carried = [], ((0.0, 0.0, 0.0), (0.0, 0.0, 0.0, 1.0))   # carried: the next origin's frame so far
    for joint in reversed(path):
        if joint.kind == "fixed":
            frame0 = compose(description.bodies[joint.body0].pose, joint.pose0)
            frame1 = compose(description.bodies[joint.body1].pose, joint.pose1)
            carried = compose(compose(carried, joint.pose0), compose(relative_pose(frame0, frame1), invert(joint.pose1)))
            continue
        if joint.kind != "revolute":
            raise ValueError(f"{joint.path}: a {joint.kind} joint between the arm's base and its gripper "
                             "(the IK handles revolute joints)")
        origin = compose(carried, joint.pose0)
        axis = {"X": (1, 0, 0), "Y": (0, 1, 0), "Z": (0, 0, 1)}[joint.axis]
        joints.append(Joint(joint.path.rsplit("/", 1)[-1], origin[0], (0.0, 0.0, 0.0), axis,
                            joint.lower, joint.upper, rotation=quat_matrix(origin[1])))
        carried = invert(joint.pose1)
    tool: Pose = compose(carried, attachment.pose0)
    return SerialChain(joints, tool_xyz=tool[0], tool_rotation=quat_matrix(tool[1])), root
