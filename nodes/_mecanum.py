"""Reading a mecanum robot's wheel geometry from its USD stage (HolonomicRobotUsdSetup's work).

Not a node type. The stage is read as authored (default time), in metres.
"""
ANGLE = "isaacmecanumwheel:angle"
RADIUS = "isaacmecanumwheel:radius"
_AXES = {"X": (1.0, 0.0, 0.0), "Y": (0.0, 1.0, 0.0), "Z": (0.0, 0.0, 1.0)}


class MecanumSetupError(ValueError):
    """The stage does not describe a mecanum robot at the given prims; the message names the prim."""


def read_mecanum_setup(stage, robot_path: str, com_path: str) -> tuple:
    """(radii, positions, orientations (w, x, y, z), angles, wheel axis, up axis, joint names) of the robot."""
    from pxr import Gf, Usd, UsdGeom, UsdPhysics

    robot = stage.GetPrimAtPath(robot_path)
    if not robot:
        raise MecanumSetupError(f"no prim {robot_path} on the stage")
    com = stage.GetPrimAtPath(com_path)
    if not com:
        raise MecanumSetupError(f"no centre-of-mass prim {com_path} on the stage")
    joints = [prim for prim in Usd.PrimRange(robot) if prim.GetAttribute(ANGLE)]
    if not joints:
        raise MecanumSetupError(f"no prim under {robot_path} has {ANGLE} (Isaac's mecanum wheel attributes)")
    metres = UsdGeom.GetStageMetersPerUnit(stage)
    cache = UsdGeom.XformCache(Usd.TimeCode.Default())
    com_frame = cache.GetLocalToWorldTransform(com).RemoveScaleShear()
    to_com = com_frame.GetInverse()
    radii, angles, positions, orientations = [], [], [], []
    for joint in joints:
        angles.append(float(_authored(joint, ANGLE)))
        radii.append(float(_authored(joint, RADIUS)) * metres)
        frame = _joint_frame(stage, cache, UsdPhysics.RevoluteJoint(joint), joint.GetPath(), Gf)
        in_com = frame * to_com                      # Gf row vectors: joint frame, then world -> com
        positions.append(tuple(float(c) * metres for c in in_com.ExtractTranslation()))
        rotation = in_com.RemoveScaleShear().ExtractRotationQuat()
        orientations.append((rotation.GetReal(), *(float(c) for c in rotation.GetImaginary())))
    axis_token = UsdPhysics.RevoluteJoint(joints[-1]).GetAxisAttr().Get()
    if axis_token not in _AXES:
        raise MecanumSetupError(f"{joints[-1].GetPath()}: physics:axis is {axis_token!r}, not X, Y or Z")
    names = tuple(joint.GetName() for joint in joints)
    return (tuple(radii), tuple(positions), tuple(orientations), tuple(angles), _AXES[axis_token],
            _AXES[UsdGeom.GetStageUpAxis(stage)], names)


def _authored(prim, name: str):
    value = prim.GetAttribute(name).Get()
    if value is None:
        raise MecanumSetupError(f"{prim.GetPath()}: {name} has no value")
    return value


def _joint_frame(stage, cache, joint, path, Gf):
    """The joint's frame in the world: localPos0 / localRot0 in its body0 prim's world transform."""
    targets = joint.GetBody0Rel().GetTargets()
    body = stage.GetPrimAtPath(targets[0]) if targets else None
    if not body:
        raise MecanumSetupError(f"{path}: physics:body0 names no prim (the chassis the wheel turns on)")
    local = Gf.Matrix4d(1.0)
    local.SetRotateOnly(Gf.Quatd(joint.GetLocalRot0Attr().Get() or Gf.Quatf(1.0)))
    local.SetTranslateOnly(Gf.Vec3d(joint.GetLocalPos0Attr().Get() or Gf.Vec3f(0.0)))
    return local * cache.GetLocalToWorldTransform(body)
