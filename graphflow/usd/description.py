"""What a physics stage describes, as plain Python data (no pxr, no pybullet).

The importer (``graphflow.usd.physics_import``) fills these from a USD stage;
the PyBullet backend builds its world from them, and rebuilds from the same
description on reset, which is what makes reset bit-exact.

Units are SI whatever the stage's ``metersPerUnit``: metres, kilograms,
seconds, radians (USD's degrees are converted), quaternions (x, y, z, w).
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import TypedDict

from graphflow.poses import AXIS_VECTORS, IDENTITY_POSE, Pose, Quat, Vec3, compose, relative, twist_angle

SHAPE_KINDS = ("box", "sphere", "capsule", "cylinder", "cone", "plane", "convex_mesh", "triangle_mesh")
JOINT_KINDS = ("fixed", "revolute", "prismatic", "spherical", "d6")


@dataclass(frozen=True)
class Material:
    static_friction: float = 0.5      # PhysX defaults
    dynamic_friction: float = 0.5
    restitution: float = 0.0


@dataclass(frozen=True)
class Shape:
    """One collision shape. ``pose`` is relative to its body (world pose for a static collider)."""

    path: str
    kind: str
    pose: Pose
    half_extents: Vec3 = (0.0, 0.0, 0.0)   # box
    radius: float = 0.0                     # sphere, capsule, cylinder, cone
    half_height: float = 0.0                # capsule/cylinder (cylinder part), cone
    axis: str = "Z"                         # capsule, cylinder, cone, plane normal
    points: tuple[Vec3, ...] = ()           # meshes, already scaled, in the shape frame
    triangles: tuple[tuple[int, int, int], ...] = ()  # triangle_mesh only
    material: Material = Material()
    collision_enabled: bool = True


class ShapeCommon(TypedDict):
    """The ``Shape`` fields every kind of collider has, as keyword arguments (the importer passes them on)."""

    path: str
    pose: Pose
    material: Material
    collision_enabled: bool


@dataclass(frozen=True)
class MassProperties:
    mass: float
    center_of_mass: Vec3                    # in the body frame
    diagonal_inertia: Vec3                  # about the principal axes
    principal_axes: Quat                    # principal axes in the body frame


@dataclass
class Body:
    """A rigid body (``dynamic`` or ``kinematic``) or a static collider (``static``)."""

    path: str
    kind: str                               # "dynamic", "kinematic", "static"
    pose: Pose                              # world pose, scale removed
    shapes: list[Shape] = field(default_factory=list)
    mass: MassProperties | None = None      # None for static
    linear_velocity: Vec3 = (0.0, 0.0, 0.0)   # world frame, m/s
    angular_velocity: Vec3 = (0.0, 0.0, 0.0)  # world frame, rad/s
    gravity_enabled: bool = True            # physxRigidBody:disableGravity
    linear_damping: float = 0.0             # PhysX defaults
    angular_damping: float = 0.05

    @property
    def mass_properties(self) -> MassProperties:
        """The mass properties of a dynamic or kinematic body; the import gives every one of them some."""
        if self.mass is None:
            raise ValueError(f"{self.path} is a static collider: it has no mass")
        return self.mass


@dataclass(frozen=True)
class Drive:
    """A joint drive: force = k (target - q) + d (target_velocity - v), clamped to max_force.

    ``acceleration`` drives scale the result by the joint's effective inertia,
    like PhysX. Angular values are per radian.
    """

    stiffness: float
    damping: float
    max_force: float
    target_position: float
    target_velocity: float
    acceleration: bool


@dataclass(frozen=True)
class AxisLimit:
    low: float
    high: float

    @property
    def locked(self) -> bool:
        """USD convention: low > high means the axis is locked."""
        return self.low > self.high


@dataclass
class Joint:
    """A joint between two bodies (``body0``/``body1`` None = the world).

    ``pose0``/``pose1`` are the joint frames in each body's frame (scale removed);
    when a body is the world, its pose is the joint frame in world.
    """

    path: str
    kind: str
    body0: str | None
    body1: str | None
    pose0: Pose = IDENTITY_POSE
    pose1: Pose = IDENTITY_POSE
    axis: str = "X"
    lower: float = float("-inf")            # revolute: rad, prismatic: m
    upper: float = float("inf")
    drive: Drive | None = None
    max_velocity: float | None = None       # rad/s or m/s (physxJoint:maxJointVelocity)
    initial_position: float | None = None   # state:*:physics:position, converted
    initial_velocity: float = 0.0
    collision_enabled: bool = False
    enabled: bool = True
    exclude_from_articulation: bool = False
    # D6 only: per axis (transX..rotZ) limits and drives, rot values in radians
    limits: dict[str, AxisLimit] = field(default_factory=dict)
    drives: dict[str, Drive] = field(default_factory=dict)
    break_force: float = float("inf")
    break_torque: float = float("inf")


@dataclass
class Articulation:
    """An articulation root and the joints and bodies that belong to it."""

    path: str
    bodies: list[str]
    joints: list[str]
    self_collision: bool = False
    roots: list[str] = field(default_factory=list)   # usd-core's root prims: a body, or the joint to the world


@dataclass(frozen=True)
class SurfaceGripper:
    path: str
    attachment_points: tuple[str, ...]


@dataclass
class StageDescription:
    source: str                             # file path or "<in-memory stage>"
    up_axis: str
    meters_per_unit: float
    gravity: Vec3
    time_step: float | None                 # from physxScene:timeStepsPerSecond
    # authored solver iteration counts: "sceneMin"/"sceneMax" (physxScene:{min,max}PositionIterationCount),
    # "bodies" (the largest physx{RigidBody,Articulation}:solverPositionIterationCount)
    solver_iterations: dict[str, int] = field(default_factory=dict)
    bodies: dict[str, Body] = field(default_factory=dict)
    joints: dict[str, Joint] = field(default_factory=dict)
    articulations: list[Articulation] = field(default_factory=list)
    surface_grippers: list[SurfaceGripper] = field(default_factory=list)
    unsupported: list[tuple[str, str]] = field(default_factory=list)   # (path, reason)
    ignored: list[tuple[str, str]] = field(default_factory=list)       # (path, what): other simulators' authoring

    @property
    def attachment_joints(self) -> dict[str, Joint]:
        """D6 joints excluded from articulation: the surface gripper's attachment points."""
        return {path: joint for path, joint in self.joints.items()
                if joint.kind == "d6" and joint.exclude_from_articulation}


def in_path_order(description: StageDescription) -> StageDescription:
    """USD's parser works in parallel and returns prims in varying order; the world is built in
    this order, and PyBullet's results depend on creation order, so sort everything by path."""
    description.bodies = dict(sorted(description.bodies.items()))
    for body in description.bodies.values():
        body.shapes.sort(key=lambda shape: shape.path)
    description.joints = dict(sorted(description.joints.items()))
    description.articulations.sort(key=lambda articulation: articulation.path)
    for articulation in description.articulations:
        articulation.bodies.sort()
        articulation.joints.sort()
    description.surface_grippers.sort(key=lambda gripper: gripper.path)
    description.unsupported.sort()
    return description


def joint_frame_offset(joint: Joint, pose0_world: Pose, pose1_world: Pose) -> float:
    """The joint coordinate implied by two body poses (rad for revolute, m for prismatic)."""
    frame0, frame1 = compose(pose0_world, joint.pose0), compose(pose1_world, joint.pose1)
    offset = relative(frame0, frame1)
    axis = AXIS_VECTORS[joint.axis]
    if joint.kind == "revolute":
        return twist_angle(offset[1], axis)
    return sum(p * a for p, a in zip(offset[0], axis))
