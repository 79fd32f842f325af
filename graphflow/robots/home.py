"""The home pose: which joint values, and authoring them as body transforms and joint states.

The values come from, first to last: ``--home NAME=VALUE,...`` (rad, or m for a prismatic joint);
the MJCF keyframe named "home" (else the first keyframe); the middle of each joint's range, with a
range wider than a full turn or unbounded on a side taken as 0 (a UR's +-360 degree joints rest at 0,
not at an arbitrary end). The links are then authored at that pose (each body's transform, by forward
kinematics down the joint tree), with PhysX's joint state (``state:*:physics:position``) at the same
value, as graphflow's UR10 asset is.
"""
from __future__ import annotations

import math

from graphflow.errors import BadInput
from graphflow.poses import AXIS_VECTORS, IDENTITY_POSE, Pose, compose, invert, quat_from_axis_angle, relative
from graphflow.usd.description import Joint, StageDescription

MOVABLE = ("revolute", "prismatic")


def parse_home(text: str) -> dict[str, float]:
    """``NAME=VALUE,NAME=VALUE`` -> {name: value}; a bad item is a BadInput naming it."""
    values: dict[str, float] = {}
    for item in filter(None, (part.strip() for part in text.split(","))):
        name, sep, value = item.partition("=")
        try:
            if not sep or not name.strip():
                raise ValueError
            values[name.strip()] = float(value)
        except ValueError:
            raise BadInput(f"--home: {item!r} is not NAME=VALUE (a joint name and radians or metres)") from None
    return values


def movable_joints(description: StageDescription) -> list[Joint]:
    """The revolute and prismatic joints between two bodies, in path order."""
    return [joint for joint in description.joints.values()
            if joint.kind in MOVABLE and not joint.exclude_from_articulation]


def range_middle(joint: Joint) -> float:
    """The rule's home value of a joint with no other: its range's middle; 0 for an unbounded or > 1 turn range."""
    lower, upper = joint.lower, joint.upper
    if not (math.isfinite(lower) and math.isfinite(upper)):
        return 0.0
    if joint.kind == "revolute" and upper - lower > 2.0 * math.pi:
        return min(max(0.0, lower), upper)
    return 0.5 * (lower + upper)


def choose_home(description: StageDescription, given: dict[str, float], keyframe: dict[str, float],
                ) -> tuple[dict[str, float], dict[str, str]]:
    """({joint path: value}, {joint path: where the value came from}); a name *given* that no joint has is
    a BadInput, as is a value outside the joint's range."""
    joints = movable_joints(description)
    names = {joint.path.rsplit("/", 1)[-1]: joint for joint in joints}
    unknown = sorted(set(given) - set(names))
    if unknown:
        raise BadInput(f"--home: no movable joint named {', '.join(unknown)} (joints: {', '.join(sorted(names))})")
    values, sources = {}, {}
    for name, joint in names.items():
        if name in given:
            value, source = given[name], "--home"
        elif name in keyframe:
            value, source = keyframe[name], "keyframe"
        else:
            value, source = range_middle(joint), "range middle"
        if not joint.lower - 1e-9 <= value <= joint.upper + 1e-9:
            raise BadInput(f"home of {name}: {value:g} is outside its range [{joint.lower:g}, {joint.upper:g}]")
        values[joint.path], sources[joint.path] = value, source
    return values, sources


def posed_bodies(description: StageDescription, home: dict[str, float]) -> dict[str, Pose]:
    """World poses of the bodies with the movable joints at *home*, walking the joint tree out from the bodies
    no joint moves; a fixed joint keeps the offset its bodies are authored at."""
    poses = {path: body.pose for path, body in description.bodies.items()}
    links = [(joint.body0, joint.body1, joint) for joint in description.joints.values()
             if joint.body0 is not None and joint.body1 is not None and not joint.exclude_from_articulation]
    moved = {child for _parent, child, _joint in links}
    placed = {path for path in poses if path not in moved}
    pending = True
    while pending:
        pending = False
        for parent, child, joint in links:
            if parent in placed and child not in placed:
                frame = compose(poses[parent], joint.pose0)
                poses[child] = compose(compose(frame, _joint_motion(description, joint, home)), invert(joint.pose1))
                placed.add(child)
                pending = True
    return poses


def _joint_motion(description: StageDescription, joint: Joint, home: dict[str, float]) -> Pose:
    """Joint frame 1 in joint frame 0: the motion at the home value, or the authored offset of a fixed joint."""
    if joint.kind not in MOVABLE or joint.path not in home:
        pose0, pose1 = (description.bodies[body].pose if body else IDENTITY_POSE for body in (joint.body0, joint.body1))
        return relative(compose(pose0, joint.pose0), compose(pose1, joint.pose1))
    axis, value = AXIS_VECTORS[joint.axis], home[joint.path]
    if joint.kind == "revolute":
        return (0.0, 0.0, 0.0), quat_from_axis_angle(axis, value)
    return (axis[0] * value, axis[1] * value, axis[2] * value), (0.0, 0.0, 0.0, 1.0)


def author_home(stage, description: StageDescription, home: dict[str, float]) -> None:
    """Write the links' transforms at *home* and each movable joint's state (PhysX JointStateAPI) on *stage*."""
    from pxr import Sdf, UsdGeom

    poses = posed_bodies(description, home)
    cache = UsdGeom.XformCache()
    for path in sorted(description.bodies, key=lambda p: p.count("/")):   # parents before children
        body = description.bodies[path]
        if body.kind != "dynamic" or poses[path] == body.pose:
            continue
        prim = stage.GetPrimAtPath(path)
        parent = prim.GetParent()
        parent_pose = poses.get(str(parent.GetPath())) or _gf_pose(cache.GetLocalToWorldTransform(parent))
        local = relative(parent_pose, poses[path])
        _set_local_pose(UsdGeom.Xformable(prim), local)
    for path, value in home.items():
        joint = description.joints[path]
        angular = joint.kind == "revolute"
        state = "angular" if angular else "linear"
        prim = stage.GetPrimAtPath(path)
        prim.AddAppliedSchema(f"PhysicsJointStateAPI:{state}")
        authored = math.degrees(value) if angular else value
        prim.CreateAttribute(f"state:{state}:physics:position", Sdf.ValueTypeNames.Float).Set(authored)
        prim.CreateAttribute(f"state:{state}:physics:velocity", Sdf.ValueTypeNames.Float).Set(0.0)


def _gf_pose(matrix) -> Pose:
    from pxr import Gf

    transform = Gf.Transform(Gf.Matrix4d(matrix))
    t, q = transform.GetTranslation(), transform.GetRotation().GetQuat()
    i = q.GetImaginary()
    return (float(t[0]), float(t[1]), float(t[2])), (float(i[0]), float(i[1]), float(i[2]), float(q.GetReal()))


def _set_local_pose(xformable, local: Pose) -> None:
    """Set the prim's translate and orient ops (in their authored precision), adding them if absent."""
    from pxr import Gf, UsdGeom

    (x, y, z), (qx, qy, qz, qw) = local
    ops = {op.GetOpType(): op for op in xformable.GetOrderedXformOps()}
    translate = ops.get(UsdGeom.XformOp.TypeTranslate) or xformable.AddTranslateOp()
    orient = ops.get(UsdGeom.XformOp.TypeOrient) or xformable.AddOrientOp()
    double = UsdGeom.XformOp.PrecisionDouble
    translate.Set(Gf.Vec3d(x, y, z) if translate.GetPrecision() == double else Gf.Vec3f(x, y, z))
    orient.Set(Gf.Quatd(qw, qx, qy, qz) if orient.GetPrecision() == double else Gf.Quatf(qw, qx, qy, qz))
