"""Small stand-ins for the physics world, for unit tests of robot nodes without PyBullet."""
from graphflow.world import ClockWorld, WorldError


class FakeArticulationWorld(ClockWorld):
    """A clock with articulations whose joint targets are recorded (and, for positions, reached at once)."""

    def __init__(self, joints: dict[str, tuple[str, ...]], time_step: float = 1.0 / 60.0):
        super().__init__(time_step)
        self.joints = joints
        self.positions = {path: [0.0] * len(names) for path, names in joints.items()}
        self.calls: list[tuple] = []

    def joint_names(self, articulation_path):
        if articulation_path not in self.joints:
            raise WorldError(f"no articulation at {articulation_path}")
        return self.joints[articulation_path]

    def joint_positions(self, articulation_path):
        return tuple(self.positions[articulation_path])

    def set_joint_targets(self, articulation_path, indices, *, positions=None, velocities=None, efforts=None):
        self.joint_names(articulation_path)
        self.calls.append((articulation_path, tuple(indices), positions and tuple(positions),
                           velocities and tuple(velocities), efforts and tuple(efforts)))
        for index, value in zip(indices, positions or ()):
            self.positions[articulation_path][index] = value
