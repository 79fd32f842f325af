"""Small real arms written as UsdPhysics .usda from published numbers, and their static gravity torques from numpy.

UR5e: Universal Robots' published DH and dynamics table ("DH parameters for calculations of
kinematics and dynamics": link lengths, masses, centres of mass in the DH frames) with MuJoCo
Menagerie's actuator gains (kp 2000 / kv 400 on the big joints, 500 / 100 on the wrist).
Panda-like: Franka's modified-DH kinematics, the masses and centres of mass of the published
dynamic identification (Gaz et al. 2019), Menagerie's gains, and each link's principal axes turned
away from its frame (as a converted URDF's full inertia tensor gives them).

The reference never touches graphflow: forward kinematics in numpy, the gravity torque on joint j
z_j . sum_i (c_i - o_j) x m_i g over the links beyond it, and the static equilibrium k (q - q*) = tau_g(q)
solved by fixed-point iteration.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from pxr import Gf, Sdf, Usd, UsdGeom, UsdPhysics

G = 9.81


@dataclass(frozen=True)
class Arm:
    name: str
    frames: tuple            # per DH row: a function q -> 4x4 transform of frame i in frame i-1
    joint_in_child: bool     # modified DH: joint i turns about z_i (True); standard DH: about z_{i-1}
    masses: tuple
    centres: tuple           # per link, in its DH frame
    inertias: tuple          # per link, principal moments (kg m^2)
    axes: tuple              # per link, principal axes as (w, x, y, z)
    stiffness: tuple         # N m / rad
    damping: tuple           # N m s / rad
    home: tuple              # rad: the drive targets and the start

    def transforms(self, q) -> list[np.ndarray]:
        """World transform of every link frame (index 0 the base) at joint positions *q*."""
        frames = [np.eye(4)]
        for row, angle in zip(self.frames, q):
            frames.append(frames[-1] @ row(angle))
        return frames

    def gravity_torques(self, q) -> np.ndarray:
        """tau_g: the torque gravity puts on each joint (what a drive must oppose) at *q*."""
        frames = self.transforms(q)
        weight = np.array([0.0, 0.0, -G])
        centres = [frames[i + 1] @ np.append(c, 1.0) for i, c in enumerate(self.centres)]
        torques = []
        for j in range(len(q)):
            joint_frame = frames[j + 1] if self.joint_in_child else frames[j]
            axis, origin = joint_frame[:3, 2], joint_frame[:3, 3]
            torques.append(sum(axis @ np.cross(c[:3] - origin, m * weight)
                               for m, c in zip(self.masses[j:], centres[j:])))
        return np.array(torques)

    def static_positions(self) -> np.ndarray:
        """Where the drives hold the arm: k (q - q*) = tau_g(q), by fixed-point iteration."""
        home, stiffness = np.array(self.home), np.array(self.stiffness)
        q = home.copy()
        for _ in range(100):
            q = home + self.gravity_torques(q) / stiffness
        return q


def _standard_dh(a, d, alpha):
    def row(theta):
        ct, st, ca, sa = math.cos(theta), math.sin(theta), math.cos(alpha), math.sin(alpha)
        return np.array([[ct, -st * ca, st * sa, a * ct], [st, ct * ca, -ct * sa, a * st],
                         [0, sa, ca, d], [0, 0, 0, 1]])
    return row


def _modified_dh(a, d, alpha):
    def row(theta):
        ct, st, ca, sa = math.cos(theta), math.sin(theta), math.cos(alpha), math.sin(alpha)
        return np.array([[ct, -st, 0, a], [st * ca, ct * ca, -sa, -d * sa],
                         [st * sa, ct * sa, ca, d * ca], [0, 0, 0, 1]])
    return row


def _turned(axis, degrees):
    """(w, x, y, z) of a turn by *degrees* about *axis*."""
    axis = np.asarray(axis, dtype=float) / np.linalg.norm(axis)
    half = math.radians(degrees) / 2
    return (math.cos(half), *(math.sin(half) * axis))


_IDENTITY = (1.0, 0.0, 0.0, 0.0)

UR5E = Arm(
    name="ur5e",
    frames=tuple(_standard_dh(a, d, alpha) for a, d, alpha in (
        (0.0, 0.1625, math.pi / 2), (-0.425, 0.0, 0.0), (-0.3922, 0.0, 0.0),
        (0.0, 0.1333, math.pi / 2), (0.0, 0.0997, -math.pi / 2), (0.0, 0.0996, 0.0))),
    joint_in_child=False,
    masses=(3.761, 8.058, 2.846, 1.37, 1.3, 0.365),
    centres=((0, -0.02561, 0.00193), (0.2125, 0, 0.11336), (0.15, 0.0, 0.0265),
             (0, -0.0018, 0.01634), (0, 0.0018, 0.01634), (0, 0, -0.001159)),
    inertias=((0.0103, 0.0103, 0.0067), (0.0300, 0.1310, 0.1310), (0.0042, 0.0404, 0.0404),
              (0.0027, 0.0027, 0.0020), (0.0025, 0.0025, 0.0019), (0.0003, 0.0003, 0.0004)),
    axes=(_IDENTITY,) * 6,
    stiffness=(2000.0, 2000.0, 2000.0, 500.0, 500.0, 500.0),
    damping=(400.0, 400.0, 400.0, 100.0, 100.0, 100.0),
    home=(0.0, -math.pi / 2 + 0.6, 0.9, -0.4, 0.3, 0.0),
)

PANDA = Arm(
    name="panda",
    frames=tuple(_modified_dh(a, d, alpha) for a, d, alpha in (
        (0.0, 0.333, 0.0), (0.0, 0.0, -math.pi / 2), (0.0, 0.316, math.pi / 2), (0.0825, 0.0, math.pi / 2),
        (-0.0825, 0.384, -math.pi / 2), (0.0, 0.0, math.pi / 2), (0.088, 0.0, math.pi / 2))),
    joint_in_child=True,
    masses=(4.970684, 0.646926, 3.228604, 3.587895, 1.225946, 1.666555, 0.735522),
    centres=((3.875e-3, 2.081e-3, -0.1750), (-3.141e-3, -2.872e-2, 3.495e-3), (2.7518e-2, 3.9252e-2, -6.6502e-2),
             (-5.317e-2, 1.04419e-1, 2.7454e-2), (-1.1953e-2, 4.1065e-2, -3.8437e-2),
             (6.0149e-2, -1.4117e-2, -1.0517e-2), (1.0517e-2, -4.252e-3, 6.1597e-2)),
    inertias=((0.7034, 0.7066, 0.0091), (0.0080, 0.0281, 0.0283), (0.0372, 0.0361, 0.0108),
              (0.0259, 0.0195, 0.0283), (0.0355, 0.0294, 0.0086), (0.0020, 0.0043, 0.0054),
              (0.0125, 0.0100, 0.0048)),
    axes=(_turned((1, 0, 0), 25), _turned((0, 1, 1), 40), _turned((1, 1, 0), 60), _turned((0, 0, 1), 35),
          _turned((1, -1, 1), 50), _turned((0, 1, 0), 70), _turned((1, 0, 1), 30)),
    stiffness=(4500.0, 4500.0, 3500.0, 3500.0, 2000.0, 2000.0, 2000.0),
    damping=(450.0, 450.0, 350.0, 350.0, 200.0, 200.0, 200.0),
    home=(0.0, -math.pi / 4 + 0.5, 0.0, -3 * math.pi / 4, 0.0, math.pi / 2, math.pi / 4),
)


def _pose(matrix: np.ndarray) -> tuple[Gf.Vec3d, Gf.Quatf]:
    rotation = Gf.Matrix4d(*matrix.T.flatten().tolist())      # Gf is row-vector: transpose
    return Gf.Vec3d(*matrix[:3, 3]), Gf.Quatf(rotation.ExtractRotationQuat())


def write_usda(arm: Arm, path) -> str:
    """The arm as a .usda: a fixed base, one rigid body per link at its zero-pose frame (MassAPI mass,
    centre of mass, principal moments and axes, no colliders), revolute joints about Z of the joint frame
    with angular drives (USD gains per degree) aiming at the home pose, where the joints start."""
    stage = Usd.Stage.CreateNew(str(path))
    UsdGeom.SetStageUpAxis(stage, UsdGeom.Tokens.z)
    UsdGeom.SetStageMetersPerUnit(stage, 1.0)
    UsdPhysics.Scene.Define(stage, "/World/PhysicsScene")
    root = UsdGeom.Xform.Define(stage, "/World/Arm")
    UsdPhysics.ArticulationRootAPI.Apply(root.GetPrim())
    frames = arm.transforms([0.0] * len(arm.masses))
    links = ["/World/Arm/base"] + [f"/World/Arm/link{i + 1}" for i in range(len(arm.masses))]
    for index, (link, frame) in enumerate(zip(links, frames)):
        xform = UsdGeom.Xform.Define(stage, link)
        position, orientation = _pose(frame)
        xform.AddTranslateOp().Set(position)
        xform.AddOrientOp().Set(orientation)
        UsdPhysics.RigidBodyAPI.Apply(xform.GetPrim())
        mass = UsdPhysics.MassAPI.Apply(xform.GetPrim())
        if index == 0:
            mass.CreateMassAttr(4.0)
            mass.CreateDiagonalInertiaAttr(Gf.Vec3f(0.01, 0.01, 0.01))
            continue
        mass.CreateMassAttr(arm.masses[index - 1])
        mass.CreateCenterOfMassAttr(Gf.Vec3f(*arm.centres[index - 1]))
        mass.CreateDiagonalInertiaAttr(Gf.Vec3f(*arm.inertias[index - 1]))
        w, x, y, z = arm.axes[index - 1]
        mass.CreatePrincipalAxesAttr(Gf.Quatf(w, x, y, z))
    anchor = UsdPhysics.FixedJoint.Define(stage, "/World/Arm/anchor")
    anchor.CreateBody1Rel().SetTargets([links[0]])
    for j in range(len(arm.masses)):
        joint = UsdPhysics.RevoluteJoint.Define(stage, f"/World/Arm/joint{j + 1}")
        joint.CreateBody0Rel().SetTargets([links[j]])
        joint.CreateBody1Rel().SetTargets([links[j + 1]])
        # the joint frame: frame j (standard DH) or frame j+1 (modified DH) at zero pose, in each body
        joint_frame = frames[j + 1] if arm.joint_in_child else frames[j]
        for body, (pos_attr, rot_attr) in ((frames[j], (joint.CreateLocalPos0Attr, joint.CreateLocalRot0Attr)),
                                           (frames[j + 1], (joint.CreateLocalPos1Attr, joint.CreateLocalRot1Attr))):
            position, orientation = _pose(np.linalg.inv(body) @ joint_frame)
            pos_attr(Gf.Vec3f(position))
            rot_attr(orientation)
        joint.CreateAxisAttr("Z")
        drive = UsdPhysics.DriveAPI.Apply(joint.GetPrim(), "angular")
        drive.CreateTypeAttr("force")
        drive.CreateStiffnessAttr(arm.stiffness[j] * math.pi / 180)
        drive.CreateDampingAttr(arm.damping[j] * math.pi / 180)
        drive.CreateTargetPositionAttr(math.degrees(arm.home[j]))
        joint.GetPrim().CreateAttribute("state:angular:physics:position", Sdf.ValueTypeNames.Float).Set(
            math.degrees(arm.home[j]))
    stage.GetRootLayer().Save()
    return str(path)
