"""Small stand-ins for the physics world, for unit tests of robot nodes without PyBullet."""
from graphflow.gripper.manager import SurfaceGripperManager
from graphflow.world import ClockWorld, WorldError


class FakeArticulationWorld(ClockWorld):
    """A clock with articulations whose joint targets are recorded (and, for positions, reached at once)."""

    def __init__(self, joints: dict[str, tuple[str, ...]], time_step: float = 1.0 / 60.0):
        super().__init__(time_step)
        self.joints = joints
        self.positions = {path: [0.0] * len(names) for path, names in joints.items()}
        self.efforts = {path: [0.0] * len(names) for path, names in joints.items()}
        self.calls: list[tuple] = []

    def joint_names(self, articulation_path):
        if articulation_path not in self.joints:
            raise WorldError(f"no articulation at {articulation_path}")
        return self.joints[articulation_path]

    def joint_positions(self, articulation_path):
        return tuple(self.positions[articulation_path])

    def joint_efforts(self, articulation_path):
        """Ideal actuators: the efforts applied are the ones last commanded."""
        return tuple(self.efforts[articulation_path])

    def set_joint_targets(self, articulation_path, indices, *, positions=None, velocities=None, efforts=None):
        self.joint_names(articulation_path)
        self.calls.append((articulation_path, tuple(indices), positions and tuple(positions),
                           velocities and tuple(velocities), efforts and tuple(efforts)))
        for index, value in zip(indices, positions or ()):
            self.positions[articulation_path][index] = value
        for index, value in zip(indices, efforts or ()):
            self.efforts[articulation_path][index] = value


UR10_JOINTS = ("shoulder_pan_joint", "shoulder_lift_joint", "elbow_joint", "wrist_1_joint", "wrist_2_joint",
               "wrist_3_joint")


class FakeGripperManager:
    """Records gripper commands with the world step they came in; reports what the test says is gripped."""

    def __init__(self, world, grippers):
        self.world = world
        self.grippers = set(grippers)
        self.commands: list[tuple[int, str, str]] = []
        self.status = {path: "Open" for path in grippers}
        self.holds: dict[str, str] = {}      # gripper -> object a close grips (set by the test)
        self.gripped: dict[str, list[str]] = {path: [] for path in grippers}
        self.reason = ""

    def get_gripper_status(self, path):
        return self.status[path]

    def get_gripped_objects(self, path):
        return list(self.gripped[path])

    def component(self, path):
        """The real manager's component carries ``reason``; the fake itself stands in for it."""
        return self

    def after_step(self, dt):
        """Commands take effect at once here; nothing to do per step."""

    def reset(self):
        self.status = dict.fromkeys(self.grippers, "Open")

    def close_gripper(self, path):
        if path not in self.grippers:
            return False
        self.commands.append((self.world.step_index, "close", path))
        self.status[path] = "Closed"
        self.gripped[path] = [self.holds[path]] if path in self.holds else []
        return True

    def open_gripper(self, path):
        if path not in self.grippers:
            return False
        self.commands.append((self.world.step_index, "open", path))
        self.status[path] = "Open"
        self.gripped[path] = []
        return True


class FakeUR10World(FakeArticulationWorld):
    """A UR10 at /World/ur10 (base at *base_position*) whose joints reach their targets at once,
    a gripper manager, and prims with fixed poses."""

    def __init__(self, base_position=(0.0, 0.0, 0.0), poses=None, time_step: float = 1.0 / 60.0):
        super().__init__({"/World/ur10": UR10_JOINTS}, time_step)
        from graphflow.kinematics import UR10_DEFAULT_JOINTS

        self.positions["/World/ur10"] = list(UR10_DEFAULT_JOINTS)
        self.poses = {"/World/ur10": (tuple(base_position), (0.0, 0.0, 0.0, 1.0)), **(poses or {})}
        self.services.add(FakeGripperManager(self, ["/World/ur10/ee_link/SurfaceGripper"]), SurfaceGripperManager)

    @property
    def surface_grippers(self) -> "FakeGripperManager":
        return self.services.get(SurfaceGripperManager)

    def prim_pose(self, path):
        if path not in self.poses:
            raise WorldError(f"no prim {path}")
        return self.poses[path]
