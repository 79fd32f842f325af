"""What a build made in a PyBullet client: frozen handles from USD prims to PyBullet bodies, links and DOFs.

The builder (``graphflow.physics.builder``) makes them once per (re)build; the world, its lookups and its
drives read them. Live values (drive targets, masses) are the world's run-time state, not these.
"""
from __future__ import annotations

from dataclasses import dataclass, field

from graphflow.poses import Pose, invert
from graphflow.usd.description import Joint


@dataclass(frozen=True)
class BodyHandle:
    """Where a USD body lives in PyBullet and how its prim frame relates to the link's inertial frame."""

    path: str
    body_id: int
    link: int                       # -1 for a base
    kind: str                       # dynamic, kinematic, static
    inertial_in_prim: Pose          # the PyBullet inertial (COM) frame expressed in the prim frame
    mass: float                     # as built (the world keeps the live mass)
    gravity_enabled: bool
    articulation: str | None = None
    prim_in_inertial: Pose = field(init=False, repr=False, compare=False)   # the inverse, for every pose read

    def __post_init__(self) -> None:
        object.__setattr__(self, "prim_in_inertial", invert(self.inertial_in_prim))


@dataclass(frozen=True)
class DriveSpec:
    """The drive of one articulation DOF as built (SI units); its targets are run-time state of the world."""

    stiffness: float
    damping: float
    max_force: float
    acceleration: bool
    max_velocity: float | None = None     # the joint's physxJoint:maxJointVelocity, rad/s or m/s
    lower: float = float("-inf")          # the joint's limits: targets beyond them are not pursued
    upper: float = float("inf")

    @classmethod
    def for_joint(cls, joint: Joint) -> "DriveSpec | None":
        """The joint's drive as built, None for an undriven joint."""
        drive = joint.drive
        if drive is None:
            return None
        return cls(drive.stiffness, drive.damping, drive.max_force, drive.acceleration, joint.max_velocity,
                   joint.lower, joint.upper)


@dataclass(frozen=True)
class ArticulationHandle:
    path: str
    body_id: int
    fixed_base: bool
    joint_paths: tuple[str, ...]          # movable joints in DOF order
    joint_indices: tuple[int, ...]        # PyBullet joint index of each DOF
    signs: tuple[float, ...]              # USD coordinate = sign * PyBullet coordinate
    angular: tuple[bool, ...]
    drives: tuple[DriveSpec | None, ...]
    members: frozenset[str]               # root, body and joint prim paths

    @property
    def driven(self) -> bool:
        return any(drive is not None for drive in self.drives)

    @property
    def joint_names(self) -> tuple[str, ...]:
        return tuple(path.rsplit("/", 1)[-1] for path in self.joint_paths)


@dataclass
class BuiltScene:
    """What one build made in the client (lookup tables), and the prims it could not build."""

    bodies: dict[str, BodyHandle] = field(default_factory=dict)
    by_id: dict[tuple[int, int], str] = field(default_factory=dict)
    articulations: dict[str, ArticulationHandle] = field(default_factory=dict)
    joint_dofs: dict[str, tuple[str, int]] = field(default_factory=dict)   # joint path -> (articulation, DOF)
    constraints: dict[str, list[int]] = field(default_factory=dict)        # joint path -> constraint ids
    unsupported: list[tuple[str, str]] = field(default_factory=list)       # (path, reason), beyond the import's
