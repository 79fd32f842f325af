"""Read a USD stage's physics into a ``StageDescription``.

Parsing is done by USD's own utility (``UsdPhysics.LoadUsdPhysicsFromRange``,
called ``UsdPhysicsLoadStageFromPrimRange`` in newer usd-core): it resolves
bodies, collider ownership, scaled shape sizes, joint frames, limits and
drives. This module only converts its results to SI units and graphflow's
conventions, and reads the few attributes the utility does not cover:
mass properties (through ``RigidBodyAPI.ComputeMassProperties``), PhysX extras
(``physxRigidBody:disableGravity``, damping, ``physxScene:timeStepsPerSecond``,
``physxJoint:maxJointVelocity``, ``physxArticulation:enabledSelfCollisions``),
the joint state (``state:{angular,linear}:physics:{position,velocity}``, the
PhysX JointStateAPI naming) and surface-gripper prims.

Unsupported physics prims and authored PhysX joint settings that are not simulated are reported
once each, one line, as ``UnsupportedPrimWarning`` (and listed in ``StageDescription.unsupported``);
non-physics prims (lights, materials, OmniGraph prims) are skipped quietly.
"""
from __future__ import annotations

import math
import os
import warnings
from pathlib import Path

from graphflow.messages import usd_message
from graphflow.poses import (
    AXIS_VECTORS,
    Pose,
    compose,
    quat_rotate,
)
from graphflow.usd.authored_values import (
    joint_problems,
    mass_problems,
    round_collider_problems,
    unit_mismatches,
)
from graphflow.usd.description import (
    Articulation,
    AxisLimit,
    Body,
    Drive,
    Joint,
    Material,
    Shape,
    ShapeCommon,
    StageDescription,
    SurfaceGripper,
    in_path_order,
)
from graphflow.usd.errors import StageError, warn_unsupported
from graphflow.usd.ignored import ignored_authoring
from graphflow.usd.mass_properties import MassPropertiesMixin, quat_of

DEFAULT_GRAVITY = 9.81                 # m/s^2, along minus the up axis
IN_MEMORY = "<in-memory stage>"
# A body with neither mass nor colliders is a frame (a converted MJCF site, a tool point): MuJoCo gives it no
# mass; PyBullet needs some, so 1 g on a 1 cm sphere (2/5 m r^2), not the 1 kg that sagged converted arms


def open_stage(stage_or_path):
    """Return ``(Usd.Stage, label)`` for a path or an open stage; raise StageError if it cannot be read."""
    from pxr import Tf, Usd

    if isinstance(stage_or_path, Usd.Stage):
        layer = stage_or_path.GetRootLayer()
        label = layer.realPath or layer.identifier or IN_MEMORY
        return stage_or_path, label
    path = Path(os.fspath(stage_or_path))
    if not path.is_file():
        raise StageError(f"{path}: no such stage file")
    from graphflow.usd.opening import open_composed

    try:
        stage = open_composed(path)
    except Tf.ErrorException as error:
        raise StageError(f"{path}: not a USD stage ({_usd_error_reason(error)})") from None
    if stage is None:
        raise StageError(f"{path}: not a USD stage")
    return stage, str(path)


def _usd_error_reason(error) -> str:
    """The first message of a Tf error (file:line:column and what is wrong), without USD's source-file preamble."""
    return usd_message(error)


def load_description(stage_or_path) -> StageDescription:
    """Parse the physics of a stage (path or ``Usd.Stage``) into SI-unit plain data."""
    stage, label = open_stage(stage_or_path)
    return _Importer(stage, label).run()


def _parse_physics(stage):
    from pxr import UsdPhysics

    parse = getattr(UsdPhysics, "UsdPhysicsLoadStageFromPrimRange", None)
    if parse is None:
        parse = UsdPhysics.LoadUsdPhysicsFromRange
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", DeprecationWarning)
        return parse(stage, ["/"])


def _enum_name(value) -> str:
    return str(value).rsplit(".", 1)[-1]


def _path(sdf_path) -> str | None:
    text = str(sdf_path)
    return text or None


def _finite_or_inf(value: float) -> float:
    value = float(value)
    return float("inf") if not math.isfinite(value) or abs(value) >= 3.0e38 else value


class _Importer(MassPropertiesMixin):
    description: StageDescription          # made by run(), which every other method serves

    def __init__(self, stage, label: str):
        from pxr import UsdGeom

        self.stage = stage
        self.label = label
        self.mpu = float(UsdGeom.GetStageMetersPerUnit(stage))
        self.up_axis = str(UsdGeom.GetStageUpAxis(stage))
        self.xform_cache = UsdGeom.XformCache()

    # -- helpers -----------------------------------------------------------------
    def _fail(self, message: str):
        raise StageError(f"{self.label}: {message}")

    def _unsupported(self, path: str, reason: str):
        self.description.unsupported.append((path, reason))
        warn_unsupported(self.label, path, reason)

    def _vec(self, v, scale: float | None = None):
        factor = self.mpu if scale is None else scale
        return (float(v[0]) * factor, float(v[1]) * factor, float(v[2]) * factor)

    def _attribute(self, prim, name: str, default=None):
        attribute = prim.GetAttribute(name)
        if attribute and attribute.HasAuthoredValue():
            return attribute.Get()
        return default

    def _world_pose(self, prim) -> Pose:
        """World pose of a prim with its scale removed, in metres."""
        from pxr import Gf

        matrix = Gf.Matrix4d(self.xform_cache.GetLocalToWorldTransform(prim))
        transform = Gf.Transform(matrix)
        return (self._vec(transform.GetTranslation()), quat_of(transform.GetRotation().GetQuat()))

    def _parent_rotation(self, prim):
        parent = prim.GetParent()
        if not parent or parent.IsPseudoRoot():
            return (0.0, 0.0, 0.0, 1.0)
        return self._world_pose(parent)[1]

    # -- main ----------------------------------------------------------------------
    def run(self) -> StageDescription:
        from pxr import UsdPhysics

        problems = self._prim_problems()
        if problems:
            raise StageError(*problems)
        parsed = _parse_physics(self.stage)
        kinds = UsdPhysics.ObjectType
        self.description = StageDescription(source=self.label, up_axis=self.up_axis, meters_per_unit=self.mpu,
                                            gravity=self._gravity(parsed.get(kinds.Scene)),
                                            time_step=self._time_step(parsed.get(kinds.Scene)))
        self.materials = self._materials(parsed.get(kinds.RigidBodyMaterial))
        shape_kinds = {kinds.CubeShape: "box", kinds.SphereShape: "sphere", kinds.CapsuleShape: "capsule",
                       kinds.CylinderShape: "cylinder", kinds.ConeShape: "cone", kinds.PlaneShape: "plane",
                       kinds.MeshShape: "mesh"}
        joint_kinds = {kinds.FixedJoint: "fixed", kinds.RevoluteJoint: "revolute", kinds.PrismaticJoint: "prismatic",
                       kinds.SphericalJoint: "spherical", kinds.D6Joint: "d6"}
        handled = set(shape_kinds) | set(joint_kinds) | {kinds.Scene, kinds.RigidBodyMaterial, kinds.RigidBody,
                                                          kinds.Articulation}
        body_descs = dict(zip(*parsed[kinds.RigidBody])) if kinds.RigidBody in parsed else {}
        shapes_by_body: dict[str, list] = {}
        for kind, name in shape_kinds.items():
            for path, desc in zip(*parsed.get(kind, ((), ()))):
                shapes_by_body.setdefault(_path(desc.rigidBody) or "", []).append((name, desc))
        self._bodies(body_descs, shapes_by_body)
        for kind, name in joint_kinds.items():
            for path, desc in zip(*parsed.get(kind, ((), ()))):
                self._joint(name, desc)
        self._articulations(parsed.get(kinds.Articulation))
        for kind, (paths, _descs) in parsed.items():
            if kind not in handled:
                for path in paths:
                    self._unsupported(str(path), f"{_enum_name(kind)} is not simulated")
        self._surface_grippers()
        self._solver_iterations(parsed.get(kinds.Scene))
        self._unsimulated_sleep()
        self.description.ignored = ignored_authoring(self.stage)
        for layer, reason in unit_mismatches(self.stage):
            self._unsupported(layer, reason)
        return in_path_order(self.description)

    def _prim_problems(self) -> list[str]:
        """What no simulation can take, every one: negative or non-finite masses, the inertias, centres of
        mass, joint frames, drive values and limits ``authored_values`` refuses, collider boxes and
        spheres of zero or non-finite size, bodies and colliders with non-finite transforms."""
        from pxr import Usd, UsdGeom, UsdPhysics

        problems = []
        for prim in Usd.PrimRange(self.stage.GetPseudoRoot()):
            if prim.IsA(UsdPhysics.Joint):
                problems.extend(joint_problems(prim, f"{self.label}: joint {prim.GetPath()}"))
            is_body, is_collider = prim.HasAPI(UsdPhysics.RigidBodyAPI), prim.HasAPI(UsdPhysics.CollisionAPI)
            if not (is_body or is_collider):
                continue
            where = f"{self.label}: {prim.GetPath()}"
            matrix = self.xform_cache.GetLocalToWorldTransform(prim)
            if not all(math.isfinite(matrix[row][column]) for row in range(4) for column in range(4)):
                problems.append(f"{where}: its transform is not finite (NaN or infinity in an xformOp)")
                continue
            mass = self._attribute(prim, "physics:mass") if prim.HasAPI(UsdPhysics.MassAPI) else None
            if mass is not None and not (math.isfinite(mass) and mass >= 0):
                problems.append(f"{where}: physics:mass is {mass!r}; a mass must be a finite number >= 0")
            if prim.HasAPI(UsdPhysics.MassAPI):
                problems.extend(mass_problems(prim, where))
            if not is_collider:
                continue
            problems.extend(round_collider_problems(prim, where))
            if prim.IsA(UsdGeom.Cube):
                size = UsdGeom.Cube(prim).GetSizeAttr().Get()
                if size is None or not (math.isfinite(size) and size > 0) or matrix.GetDeterminant3() == 0:
                    problems.append(f"{where}: a collider box of zero or invalid size (size {size!r})")
            elif prim.IsA(UsdGeom.Sphere):
                radius = UsdGeom.Sphere(prim).GetRadiusAttr().Get()
                if radius is None or not (math.isfinite(radius) and radius > 0):
                    problems.append(f"{where}: a collider sphere of zero or invalid radius ({radius!r})")
        return problems

    def _solver_iterations(self, scenes):
        """Authored PhysX iteration counts (scene range; the largest per body or articulation)."""
        counts = self.description.solver_iterations
        if scenes and scenes[0]:
            prim = self.stage.GetPrimAtPath(scenes[0][0])
            for key, name in (("sceneMin", "minPositionIterationCount"), ("sceneMax", "maxPositionIterationCount")):
                value = self._attribute(prim, f"physxScene:{name}")
                if value is not None:
                    counts[key] = int(value)
        owners = [(path, "physxRigidBody") for path in self.description.bodies]
        owners += [(articulation.path, "physxArticulation") for articulation in self.description.articulations]
        authored = [self._attribute(self.stage.GetPrimAtPath(path), f"{prefix}:solverPositionIterationCount")
                    for path, prefix in owners]
        authored = [int(value) for value in authored if value is not None]
        if authored:
            counts["bodies"] = max(authored)

    def _unsimulated_sleep(self):
        """Name the bodies and articulations with an authored PhysX sleep threshold: graphflow keeps every
        body awake (docs/physics.md: PyBullet's sleeping loses a woken body's first step)."""
        owners = [(path, "physxRigidBody") for path in self.description.bodies]
        owners += [(articulation.path, "physxArticulation") for articulation in self.description.articulations]
        for path, prefix in owners:
            if self._attribute(self.stage.GetPrimAtPath(path), f"{prefix}:sleepThreshold") is not None:
                self._unsupported(path, f"{prefix}:sleepThreshold is not simulated: bodies never sleep")

    def _gravity(self, scenes):
        up = AXIS_VECTORS.get(self.up_axis, AXIS_VECTORS["Z"])
        default = tuple(-DEFAULT_GRAVITY * c + 0.0 for c in up)
        if not scenes or not scenes[1]:
            return default
        scene = scenes[1][0]
        direction = tuple(float(c) for c in scene.gravityDirection)
        magnitude = float(scene.gravityMagnitude)
        if not math.isfinite(magnitude) or magnitude < 0:
            magnitude = DEFAULT_GRAVITY / self.mpu
        if not any(direction):
            direction = tuple(-c for c in up)
        return tuple(c * magnitude * self.mpu + 0.0 for c in direction)

    def _time_step(self, scenes):
        if not scenes or not scenes[0]:
            return None
        prim = self.stage.GetPrimAtPath(scenes[0][0])
        steps = self._attribute(prim, "physxScene:timeStepsPerSecond")
        return 1.0 / float(steps) if steps else None

    def _materials(self, materials) -> dict[str, Material]:
        if not materials:
            return {}
        return {str(path): Material(float(d.staticFriction), float(d.dynamicFriction), float(d.restitution))
                for path, d in zip(*materials)}

    # -- shapes and bodies -----------------------------------------------------------
    def _shape(self, kind: str, desc, body_path: str | None) -> Shape | None:
        path = str(desc.primPath)
        pose = (self._vec(desc.localPos), quat_of(desc.localRot))
        material = self.materials.get(str(desc.materials[0]), Material()) if len(desc.materials) else Material()
        common = ShapeCommon(path=path, pose=pose, material=material, collision_enabled=bool(desc.collisionEnabled))
        if kind == "box":
            return Shape(kind="box", half_extents=self._vec(desc.halfExtents), **common)
        if kind == "sphere":
            return Shape(kind="sphere", radius=float(desc.radius) * self.mpu, **common)
        if kind in ("capsule", "cylinder", "cone"):
            return Shape(kind=kind, radius=float(desc.radius) * self.mpu, half_height=float(desc.halfHeight) * self.mpu,
                         axis=_enum_name(desc.axis), **common)
        if kind == "plane":
            if body_path is not None:
                self._unsupported(path, "a plane collider on a moving body")
                return None
            return Shape(kind="plane", axis=_enum_name(desc.axis), **common)
        return self._mesh_shape(desc, body_path, common)

    def _mesh_shape(self, desc, body_path: str | None, common: ShapeCommon) -> Shape | None:
        from pxr import UsdGeom

        path = common["path"]
        mesh = UsdGeom.Mesh(self.stage.GetPrimAtPath(path))
        points = mesh.GetPointsAttr().Get() if mesh else None
        if not points:
            self._unsupported(path, "a mesh collider without points")
            return None
        scale = self._vec(desc.meshScale, 1.0)
        scaled = tuple((float(p[0]) * scale[0] * self.mpu, float(p[1]) * scale[1] * self.mpu,
                        float(p[2]) * scale[2] * self.mpu) for p in points)
        approximation = str(desc.approximation)
        if body_path is None and approximation in ("none", ""):
            counts = mesh.GetFaceVertexCountsAttr().Get() or []
            indices = mesh.GetFaceVertexIndicesAttr().Get() or []
            triangles: list[tuple[int, int, int]] = []
            cursor = 0
            for count in counts:
                face = indices[cursor:cursor + count]
                cursor += count
                triangles.extend((int(face[0]), int(face[i]), int(face[i + 1])) for i in range(1, count - 1))
            return Shape(kind="triangle_mesh", points=scaled, triangles=tuple(triangles), **common)
        return Shape(kind="convex_mesh", points=scaled, **common)

    def _bodies(self, body_descs, shapes_by_body):
        description = self.description
        for kind, desc in shapes_by_body.get("", []):
            shape = self._shape(kind, desc, None)
            if shape is None:
                continue
            # a static collider: its own body at the collider's world pose
            body = Body(path=shape.path, kind="static", pose=shape.pose)
            body.shapes.append(Shape(**{**shape.__dict__, "pose": ((0.0, 0.0, 0.0), (0.0, 0.0, 0.0, 1.0))}))
            description.bodies[shape.path] = body
        for sdf_path, desc in body_descs.items():
            path = str(sdf_path)
            prim = self.stage.GetPrimAtPath(path)
            enabled = bool(desc.rigidBodyEnabled)
            kind = "static" if not enabled else ("kinematic" if desc.kinematicBody else "dynamic")
            pose = (self._vec(desc.position), quat_of(desc.rotation))
            body = Body(path=path, kind=kind, pose=pose)
            for shape_kind, shape_desc in shapes_by_body.get(path, []):
                shape = self._shape(shape_kind, shape_desc, path)
                if shape is not None:
                    body.shapes.append(shape)
            if kind == "dynamic":
                parent_rotation = self._parent_rotation(prim)
                body.linear_velocity = quat_rotate(parent_rotation, self._vec(desc.linearVelocity))
                body.angular_velocity = quat_rotate(parent_rotation, self._vec(desc.angularVelocity, math.pi / 180.0))
            if kind != "static":
                body.mass = self._mass_properties(prim, body)
            body.gravity_enabled = not bool(self._attribute(prim, "physxRigidBody:disableGravity", False))
            body.linear_damping = float(self._attribute(prim, "physxRigidBody:linearDamping", body.linear_damping))
            body.angular_damping = float(self._attribute(prim, "physxRigidBody:angularDamping", body.angular_damping))
            description.bodies[path] = body

    # -- joints --------------------------------------------------------------------
    def _joint_body(self, joint_path: str, which: str, body_path, relationship_target, local_pose: Pose):
        """Resolve one side of a joint: (body path or None for the world, joint frame in that body)."""
        target = _path(relationship_target)
        resolved = _path(body_path)
        if target is not None and not self.stage.GetPrimAtPath(target):
            self._fail(f"joint {joint_path}: {which} <{target}> does not exist")
        anchor = resolved or target
        body = self.description.bodies.get(anchor) if anchor else None
        if body is not None and body.kind != "static":
            return anchor, local_pose
        if anchor is None:
            return None, local_pose
        # anchored to a static prim: the joint frame is fixed in the world
        return None, compose(self._world_pose(self.stage.GetPrimAtPath(anchor)), local_pose)

    def _drive(self, drive, angular: bool) -> Drive | None:
        """Convert a USD drive to SI: angular gains are per degree in USD (PhysX converts them by 180/pi)."""
        if drive is None or not drive.enabled:
            return None
        per_radian = 180.0 / math.pi if angular else 1.0
        force_scale = self.mpu ** 2 if angular else self.mpu          # torque or force in SI
        gain_scale = 1.0 if drive.acceleration else (force_scale if angular else 1.0)
        position_scale = math.pi / 180.0 if angular else self.mpu
        return Drive(stiffness=float(drive.stiffness) * per_radian * gain_scale,
                     damping=float(drive.damping) * per_radian * gain_scale,
                     max_force=_finite_or_inf(drive.forceLimit) * force_scale,
                     target_position=float(drive.targetPosition) * position_scale,
                     target_velocity=float(drive.targetVelocity) * position_scale,
                     acceleration=bool(drive.acceleration))

    def _joint(self, kind: str, desc):
        path = str(desc.primPath)
        prim = self.stage.GetPrimAtPath(path)
        pose0 = (self._vec(desc.localPose0Position), quat_of(desc.localPose0Orientation))
        pose1 = (self._vec(desc.localPose1Position), quat_of(desc.localPose1Orientation))
        body0, pose0 = self._joint_body(path, "body0", desc.body0, desc.rel0, pose0)
        body1, pose1 = self._joint_body(path, "body1", desc.body1, desc.rel1, pose1)
        if body0 is None and body1 is None:
            self._unsupported(path, "a joint between two static frames")
            return
        joint = Joint(path=path, kind=kind, body0=body0, body1=body1, pose0=pose0, pose1=pose1,
                      collision_enabled=bool(desc.collisionEnabled), enabled=bool(desc.jointEnabled),
                      exclude_from_articulation=bool(desc.excludeFromArticulation),
                      break_force=_finite_or_inf(desc.breakForce), break_torque=_finite_or_inf(desc.breakTorque))
        self._unsimulated_joint_settings(prim, path)
        angular = kind == "revolute"
        if kind in ("revolute", "prismatic"):
            joint.axis = _enum_name(desc.axis)
            scale = math.pi / 180.0 if angular else self.mpu
            if desc.limit.enabled:
                joint.lower = float(desc.limit.lower) * scale if math.isfinite(desc.limit.lower) else float("-inf")
                joint.upper = float(desc.limit.upper) * scale if math.isfinite(desc.limit.upper) else float("inf")
            joint.drive = self._drive(desc.drive, angular)
            state = "angular" if angular else "linear"
            position = self._attribute(prim, f"state:{state}:physics:position")
            velocity = self._attribute(prim, f"state:{state}:physics:velocity")
            joint.initial_position = float(position) * scale if position is not None else None
            joint.initial_velocity = float(velocity) * scale if velocity is not None else 0.0
            max_velocity = self._attribute(prim, "physxJoint:maxJointVelocity")
            joint.max_velocity = float(max_velocity) * scale if max_velocity is not None else None
        elif kind == "spherical":
            joint.axis = _enum_name(desc.axis)
            if desc.limit.enabled:
                self._unsupported(path, "spherical joint cone limits are not simulated")
        elif kind == "d6":
            for pair in desc.jointLimits:
                name = _axis_name(pair.first)
                scale = math.pi / 180.0 if name.startswith("rot") else self.mpu
                if pair.second.enabled:
                    joint.limits[name] = AxisLimit(float(pair.second.lower) * scale, float(pair.second.upper) * scale)
            for pair in desc.jointDrives:
                name = _axis_name(pair.first)
                drive = self._drive(pair.second, name.startswith("rot"))
                if drive is not None:
                    joint.drives[name] = drive
        self.description.joints[path] = joint

    def _unsimulated_joint_settings(self, prim, path: str):
        """Name the authored PhysX joint settings the PyBullet world does not simulate (non-zero values)."""
        ignored = []
        for attribute in prim.GetAuthoredAttributes():
            name = attribute.GetName()
            parts = name.split(":")
            if name in ("physxJoint:armature", "physxJoint:jointFriction") or (
                    parts[0] == "physxLimit" and parts[-1] in ("stiffness", "damping", "restitution",
                                                               "bounceThreshold")):
                value = attribute.Get()
                if isinstance(value, (int, float)) and value != 0:
                    ignored.append(name)
        ignored += [relationship.GetName() for relationship in prim.GetAuthoredRelationships()
                    if relationship.GetName().startswith("physxMimicJoint:")]       # a joint following another
        if ignored:
            self._unsupported(path, "PhysX joint settings not simulated: " + ", ".join(sorted(ignored)))

    def _articulations(self, articulations):
        if not articulations:
            return
        for path, desc in zip(*articulations):
            path = str(path)
            joints = [str(j) for j in desc.articulatedJoints
                      if str(j) in self.description.joints and not self.description.joints[str(j)].exclude_from_articulation]
            bodies = [str(b) for b in desc.articulatedBodies if str(b)]
            prim = self.stage.GetPrimAtPath(path)
            self_collision = bool(self._attribute(prim, "physxArticulation:enabledSelfCollisions", False))
            roots = sorted(str(r) for r in desc.rootPrims if str(r))
            self.description.articulations.append(Articulation(path=path, bodies=bodies, joints=joints,
                                                               self_collision=self_collision, roots=roots))

    def _surface_grippers(self):
        from pxr import Usd

        for prim in self.stage.Traverse(Usd.TraverseInstanceProxies()):
            if prim.GetTypeName() != "IsaacSurfaceGripper":
                continue
            relationship = prim.GetRelationship("isaac:attachmentPoints")
            targets = tuple(str(t) for t in relationship.GetTargets()) if relationship else ()
            self.description.surface_grippers.append(SurfaceGripper(str(prim.GetPath()), targets))


def _axis_name(dof) -> str:
    name = _enum_name(dof)
    return name[0].lower() + name[1:]          # TransX -> transX, RotZ -> rotZ
