"""Build PyBullet bodies, multibodies and constraints from a ``StageDescription``.

Mapping (documented in ``graphflow.physics``):

* every rigid body outside an articulation is a one-link multibody whose base
  frame is the prim frame; static colliders and kinematic bodies get mass 0;
* every articulation is one multibody (``createMultiBody`` with link arrays):
  the body fixed to the world by a fixed joint is the (mass 0) base, a body
  free in space makes a floating base (usd-core's root body, e.g. the
  krabby's chassis, else the centre of the joint graph), a movable joint to
  the world gets a massless anchor base; the tree is walked from the base
  depth first, the order in which PyBullet numbers createMultiBody links (a
  breadth-first walk misplaced every branch after the first); each link
  frame is its joint frame, so USD joint coordinates equal PyBullet's (times
  -1 when the tree runs body1 -> body0);
* joints outside articulations become constraints (fixed, prismatic, point to
  point; revolute as two point-to-point constraints on the axis);
* D6 joints with ``excludeFromArticulation`` are not built: they are the
  surface gripper's attachment points, kept as descriptions; a D6 joint from
  an articulation to the world fixes its base; bodies and joints an
  articulation's tree cannot take (off the root, closing a loop) are free
  bodies and constraints, each named once;
* a ``UsdGeom.Plane`` collider is a large static box whose top face is the
  plane, every dynamic body gets a friction anchor (``contacts``);
* friction and restitution are given to PyBullet as square roots: Bullet
  multiplies the two bodies' coefficients where PhysX averages them, so equal
  materials combine to the authored value. Bullet has one friction
  coefficient per link: the static friction of the body's first collider.
"""
from __future__ import annotations

import hashlib
import math
import os
from dataclasses import dataclass, field, replace

import pybullet

from graphflow.physics.contacts import ROLLING_SHAPES, anchor_friction, plane_box
from graphflow.physics.handles import ArticulationHandle, BodyHandle, BuiltScene, DriveSpec
from graphflow.physics.tree import floating_root
from graphflow.poses import (
    AXIS_VECTORS,
    IDENTITY_POSE,
    Pose,
    compose,
    invert,
    quat_from_axis_angle,
    quat_multiply,
)
from graphflow.usd.description import Body, Joint, Shape, StageDescription, joint_frame_offset
from graphflow.usd.errors import StageError

CONE_SEGMENTS = 24                 # a cone collider is the convex hull of this many base points and its apex
CONSTRAINT_MAX_FORCE = 1.0e9       # joints between free bodies are rigid (see pybullet_notes §4 default quirk)
REVOLUTE_PIN_HALF_SPAN = 0.25      # m: a free revolute joint is two pins this far either side on its axis

# cylinders and capsules in Bullet run along local Z; USD lets them run along X or Y
_AXIS_ALIGNMENT = {"X": quat_from_axis_angle((0.0, 1.0, 0.0), math.pi / 2.0),
                   "Y": quat_from_axis_angle((1.0, 0.0, 0.0), -math.pi / 2.0),
                   "Z": (0.0, 0.0, 0.0, 1.0)}


class SceneBuilder:
    """Creates the PyBullet objects of one description in one client; call ``build()`` once per (re)build."""

    def __init__(self, client, description: StageDescription, mesh_directory: str):
        self.p = client
        self.description = description
        self.mesh_directory = mesh_directory
        self.scene = BuiltScene()
        self._noted: set[str] = set()

    def build(self) -> BuiltScene:
        """Create everything in the client; the scene lists what was left out (the caller warns)."""
        articulated: set[str] = set()
        for articulation in self.description.articulations:
            if self._build_articulation(articulation):
                # what the multibody holds; bodies and joints it could not take are free bodies and constraints
                articulated.update(self.scene.articulations[articulation.path].members)
        for path, body in self.description.bodies.items():
            if path not in articulated:
                self._build_free_body(body)
        for path, joint in self.description.joints.items():
            if path not in articulated:
                self._build_constraint(joint)
        return self.scene

    def _unsupported(self, path: str, reason: str):
        """Note a prim the build leaves out, once (the description already lists import-time problems)."""
        if path not in self._noted:
            self._noted.add(path)
            if (path, reason) not in self.description.unsupported:
                self.scene.unsupported.append((path, reason))

    # -- collision shapes ----------------------------------------------------------
    def _collision_shape(self, shapes: list[Shape], frame: Pose = IDENTITY_POSE) -> int:
        """One PyBullet collision shape (compound if needed) for shapes posed in a body, re-expressed in *frame*."""
        p = self.p
        shapes = [s for s in shapes if s.collision_enabled]
        if not shapes:
            return -1
        single = shapes[0] if len(shapes) == 1 else None
        if single is not None and single.kind in ("plane", "triangle_mesh"):
            pose = compose(frame, single.pose)
            if single.kind == "plane":   # a large box: PyBullet's plane shape lets contacts sink and creep
                half_extents, centre = plane_box(single.axis)
                pose = compose(pose, ((centre[0], centre[1], centre[2]), (0.0, 0.0, 0.0, 1.0)))
                return p.createCollisionShape(p.GEOM_BOX, halfExtents=half_extents,
                                              collisionFramePosition=pose[0], collisionFrameOrientation=pose[1])
            return p.createCollisionShape(p.GEOM_MESH, vertices=[list(v) for v in single.points],
                                          indices=[i for tri in single.triangles for i in tri],
                                          collisionFramePosition=pose[0], collisionFrameOrientation=pose[1])
        kinds, radii, lengths, files, positions, orientations = [], [], [], [], [], []
        box_extents: list[list[float]] = []
        for shape in shapes:
            if shape.kind in ("plane", "triangle_mesh"):
                self._unsupported(shape.path, f"a {shape.kind.replace('_', ' ')} collider combined with other shapes")
                continue
            pose = compose(frame, shape.pose)
            kind, radius, extents, length, file_name = p.GEOM_BOX, 0.0, [0.0, 0.0, 0.0], 0.0, ""
            if shape.kind == "box":
                extents = list(shape.half_extents)
            elif shape.kind == "sphere":
                kind, radius = p.GEOM_SPHERE, shape.radius
            elif shape.kind in ("capsule", "cylinder"):
                kind = p.GEOM_CAPSULE if shape.kind == "capsule" else p.GEOM_CYLINDER
                radius, length = shape.radius, 2.0 * shape.half_height
                pose = (pose[0], quat_multiply(pose[1], _AXIS_ALIGNMENT[shape.axis]))
            else:  # cone and convex mesh: a convex hull of points
                kind, file_name = p.GEOM_MESH, self._hull_file(shape)
            kinds.append(kind)
            radii.append(radius)
            box_extents.append(extents)
            lengths.append(length)
            files.append(file_name)
            positions.append(list(pose[0]))
            orientations.append(list(pose[1]))
        if not kinds:
            return -1
        try:
            return p.createCollisionShapeArray(shapeTypes=kinds, radii=radii, halfExtents=box_extents,
                                               lengths=lengths, fileNames=files,
                                               meshScales=[[1.0, 1.0, 1.0]] * len(kinds),
                                               collisionFramePositions=positions,
                                               collisionFrameOrientations=orientations)
        except pybullet.error:    # e.g. a hull of two points: PyBullet says only "createCollisionShapeArray failed"
            raise StageError(f"{self.description.source}: collider {', '.join(s.path for s in shapes)}: PyBullet "
                             "cannot make a collision shape of it (a hull needs 3 points not on a line)") from None

    def _hull_file(self, shape: Shape) -> str:
        """PyBullet's compound shapes take meshes only from files: write the hull points as an OBJ once, named by
        a hash of the prim path (the path itself overran the 255-byte file-name limit on deep converted robots)."""
        points = shape.points if shape.kind == "convex_mesh" else _cone_points(shape)
        name = "hull-" + hashlib.sha256(shape.path.encode()).hexdigest()[:24] + ".obj"
        file_path = os.path.join(self.mesh_directory, name)
        if not os.path.exists(file_path):
            with open(file_path, "w", encoding="ascii") as obj:
                obj.writelines(f"v {x!r} {y!r} {z!r}\n" for x, y, z in points)
                # PyBullet's OBJ reader needs faces; a fan over the points is enough for a convex hull
                obj.writelines(f"f 1 {i} {i + 1}\n" for i in range(2, len(points)))
        return file_path

    # -- bodies ----------------------------------------------------------------------
    def _apply_dynamics(self, body_id: int, link: int, body: Body, turns: bool = False):
        p = self.p
        friction = body.shapes[0].material.static_friction if body.shapes else 0.5
        restitution = body.shapes[0].material.restitution if body.shapes else 0.0
        p.changeDynamics(body_id, link, lateralFriction=math.sqrt(max(friction, 0.0)),
                         restitution=math.sqrt(max(restitution, 0.0)),
                         linearDamping=body.linear_damping, angularDamping=body.angular_damping)
        if body.mass is not None and body.kind == "dynamic":
            p.changeDynamics(body_id, link, localInertiaDiagonal=list(body.mass.diagonal_inertia))
        if body.kind == "dynamic" and not (turns or any(shape.kind in ROLLING_SHAPES for shape in body.shapes)):
            anchor_friction(p, body_id, link)     # not on what rolls (see contacts.anchor_friction)

    def _register(self, body: Body, body_id: int, link: int, inertial_in_prim: Pose, articulation: str | None,
                  mass: float):
        handle = BodyHandle(path=body.path, body_id=body_id, link=link, kind=body.kind,
                            inertial_in_prim=inertial_in_prim, mass=mass,
                            gravity_enabled=body.gravity_enabled, articulation=articulation)
        self.scene.bodies[body.path] = handle
        self.scene.by_id[(body_id, link)] = body.path

    def _build_free_body(self, body: Body):
        p = self.p
        dynamic = body.kind == "dynamic"
        inertial = (body.mass_properties.center_of_mass, body.mass_properties.principal_axes) if dynamic else IDENTITY_POSE
        mass = body.mass_properties.mass if dynamic else 0.0
        body_id = p.createMultiBody(baseMass=mass, baseCollisionShapeIndex=self._collision_shape(body.shapes),
                                    basePosition=body.pose[0], baseOrientation=body.pose[1],
                                    baseInertialFramePosition=inertial[0],
                                    baseInertialFrameOrientation=inertial[1])
        self._apply_dynamics(body_id, -1, body)
        if dynamic:
            p.resetBaseVelocity(body_id, body.linear_velocity, body.angular_velocity)
        self._register(body, body_id, -1, inertial, None, mass)

    # -- articulations -------------------------------------------------------------------
    def _build_articulation(self, articulation) -> bool:
        """One multibody for the articulation, in named steps; False (nothing built) without dynamic bodies."""
        joints = self._articulation_joints(articulation)
        members = [b for b in articulation.bodies if b in self.description.bodies
                   and self.description.bodies[b].kind == "dynamic"]
        if not members:
            self._unsupported(articulation.path, "an articulation without dynamic bodies")
            return False
        tree = self._choose_base(articulation, members, joints)
        self._walk_tree(tree, joints)
        links = self._link_arrays(tree)
        body_id = self._create_multibody(articulation, tree, links)
        self._register_links(articulation, tree, links, body_id)
        drives = self._initialise_dofs(body_id, links.dofs)
        handle = ArticulationHandle(
            path=articulation.path, body_id=body_id, fixed_base=tree.fixed_base,
            joint_paths=tuple(j.path for _i, j, _s in links.dofs), joint_indices=tuple(i for i, *_ in links.dofs),
            signs=tuple(s for _i, _j, s in links.dofs), angular=tuple(j.kind == "revolute" for _i, j, _s in links.dofs),
            drives=drives,
            members=frozenset([articulation.path, *tree.visited - {None}, *(j.path for _c, j, _p, _b in tree.order),
                               *([tree.anchor_joint.path] if tree.anchor_joint is not None else [])]))
        self.scene.articulations[articulation.path] = handle
        for dof, path in enumerate(handle.joint_paths):
            self.scene.joint_dofs[path] = (articulation.path, dof)
        return True

    def _articulation_joints(self, articulation) -> list[Joint]:
        """The enabled joints a multibody can have (fixed, revolute, prismatic), by path; others are noted.

        A D6 joint from the articulation to the world (how Isaac's robot assets, the Franka, anchor
        their root) fixes the base, as PhysX does.
        """
        description = self.description
        joints = [description.joints[path] for path in sorted(articulation.joints)
                  if description.joints[path].enabled and description.joints[path].kind in ("fixed", "revolute",
                                                                                              "prismatic")]
        for path in sorted(articulation.joints):
            joint = description.joints[path]
            if joint.kind == "d6" and joint.enabled and (joint.body0 is None or joint.body1 is None):
                self._unsupported(path, "a D6 joint from an articulation to the world: simulated as fixed "
                                        "(its free axes are not simulated)")
                joints.append(replace(joint, kind="fixed"))
            elif joint.kind == "spherical":
                self._unsupported(path, "a spherical joint inside an articulation: simulated as a point-to-point "
                                        "constraint (no limits)")
            elif joint.kind not in ("fixed", "revolute", "prismatic"):
                self._unsupported(path, f"a {joint.kind} joint inside an articulation is not simulated")
        return joints

    def _choose_base(self, articulation, members: list[str], joints: list[Joint]) -> "_Tree":
        """The base: the body fixed to the world, a massless anchor for a movable joint to the world, or
        (free in space) a floating root. Extra joints to the world close loops: noted and dropped from *joints*."""
        world_joints = [j for j in joints if j.body0 is None or j.body1 is None]
        if not world_joints:
            return _Tree(floating_root(articulation, members, joints), False, None)
        anchor_joint = world_joints[0]
        root_body = None
        if anchor_joint.kind == "fixed":
            root_body = _body_on_world_joint(anchor_joint)
        for extra in world_joints[1:]:
            self._unsupported(extra.path, "a second joint to the world in one articulation (closed loop): "
                                          "simulated as a constraint (no limits, no drive)")
            joints.remove(extra)
        return _Tree(root_body, True, anchor_joint)

    def _walk_tree(self, tree: "_Tree", joints: list[Joint]) -> None:
        """Fill ``tree.order``: (child body, joint, parent body or None, child is body1), depth first from the base.

        PyBullet numbers the links of createMultiBody depth first (pre-order, children in array order),
        whatever the order of the arrays, so the arrays are written in that order and link i is entry i.
        """
        root_body, anchor_joint = tree.root_body, tree.anchor_joint
        tree.visited = {root_body} if root_body else set()
        start: str | None = root_body
        if anchor_joint is not None and root_body is None:
            anchored = _body_on_world_joint(anchor_joint)
            tree.order.append((anchored, anchor_joint, None, anchor_joint.body1 == anchored))
            tree.visited.add(anchored)
            start = anchored
        remaining = [j for j in joints if j is not anchor_joint]
        stack: list[str] = [start] if start is not None else []
        while stack:
            parent = stack[-1]
            joint = next((j for j in remaining if parent in (j.body0, j.body1)), None)
            if joint is None:
                stack.pop()
                continue
            remaining.remove(joint)
            child = joint.body1 if joint.body0 == parent else joint.body0
            if child in tree.visited or child is None:
                self._unsupported(joint.path, "a joint closing a loop in an articulation: simulated as a "
                                              "constraint (no limits, no drive)")
                continue
            tree.visited.add(child)
            tree.order.append((child, joint, parent, joint.body1 == child))
            stack.append(child)
        for joint in remaining:
            self._unsupported(joint.path, "a joint not connected to its articulation's root: simulated as a "
                                          "constraint between free bodies (no limits, no drive)")

    def _link_arrays(self, tree: "_Tree") -> "_Links":
        """createMultiBody's link arrays; each link frame is its joint frame (prim frames expressed in it)."""
        p = self.p
        description = self.description
        links = _Links(link_from_prim={tree.root_body: IDENTITY_POSE}, link_index={tree.root_body: -1})
        arrays = links.arrays
        for index, (child, joint, parent, child_is_body1) in enumerate(tree.order):
            child_side, parent_side = (joint.pose1, joint.pose0) if child_is_body1 else (joint.pose0, joint.pose1)
            links.link_from_prim[child] = invert(child_side)
            links.link_index[child] = index
            origin = compose(links.link_from_prim[parent], parent_side) if parent is not None else parent_side
            body = description.bodies[child]
            inertial = compose(links.link_from_prim[child], (body.mass_properties.center_of_mass, body.mass_properties.principal_axes))
            arrays["masses"].append(body.mass_properties.mass)
            arrays["shapes"].append(self._collision_shape(body.shapes, links.link_from_prim[child]))
            arrays["visuals"].append(-1)
            arrays["positions"].append(list(origin[0]))
            arrays["orientations"].append(list(origin[1]))
            arrays["inertial_positions"].append(list(inertial[0]))
            arrays["inertial_orientations"].append(list(inertial[1]))
            arrays["parents"].append(links.link_index[parent] + 1 if parent is not None else 0)
            arrays["types"].append({"fixed": p.JOINT_FIXED, "revolute": p.JOINT_REVOLUTE,
                                    "prismatic": p.JOINT_PRISMATIC}[joint.kind])
            arrays["axes"].append(list(AXIS_VECTORS[joint.axis]))
            if joint.kind != "fixed":
                links.dofs.append((index, joint, 1.0 if child_is_body1 else -1.0))
        return links

    def _create_multibody(self, articulation, tree: "_Tree", links: "_Links") -> int:
        """The multibody: base (the root body, or a massless anchor) and the link arrays."""
        p = self.p
        base_pose = self.description.bodies[tree.root_body].pose if tree.root_body else IDENTITY_POSE
        if tree.root_body is not None:
            root = self.description.bodies[tree.root_body]
            links.base_mass = 0.0 if tree.fixed_base else root.mass_properties.mass
            links.base_inertial = (root.mass_properties.center_of_mass, root.mass_properties.principal_axes)
            base_shape = self._collision_shape(root.shapes)
        else:
            base_shape = -1
        flags = p.URDF_USE_SELF_COLLISION | p.URDF_USE_SELF_COLLISION_EXCLUDE_PARENT if articulation.self_collision else 0
        arrays = links.arrays
        return p.createMultiBody(
            baseMass=links.base_mass, baseCollisionShapeIndex=base_shape, basePosition=base_pose[0],
            baseOrientation=base_pose[1], baseInertialFramePosition=links.base_inertial[0],
            baseInertialFrameOrientation=links.base_inertial[1],
            linkMasses=arrays["masses"], linkCollisionShapeIndices=arrays["shapes"],
            linkVisualShapeIndices=arrays["visuals"], linkPositions=arrays["positions"],
            linkOrientations=arrays["orientations"], linkInertialFramePositions=arrays["inertial_positions"],
            linkInertialFrameOrientations=arrays["inertial_orientations"], linkParentIndices=arrays["parents"],
            linkJointTypes=arrays["types"], linkJointAxis=arrays["axes"], flags=flags)

    def _register_links(self, articulation, tree: "_Tree", links: "_Links", body_id: int) -> None:
        """Materials, authored root velocity and a ``BodyHandle`` for the root and every link body."""
        if tree.root_body is not None:
            root = self.description.bodies[tree.root_body]
            self._apply_dynamics(body_id, -1, root)
            self._register(root, body_id, -1, links.base_inertial, articulation.path, links.base_mass)
            if not tree.fixed_base:
                self.p.resetBaseVelocity(body_id, root.linear_velocity, root.angular_velocity)
        arrays = links.arrays
        for child, joint, _parent, _is_body1 in tree.order:
            body = self.description.bodies[child]
            index = links.link_index[child]
            self._apply_dynamics(body_id, index, body, turns=joint.kind == "revolute")
            inertial_in_prim = compose(invert(links.link_from_prim[child]),
                                       (tuple(arrays["inertial_positions"][index]),
                                        tuple(arrays["inertial_orientations"][index])))
            self._register(body, body_id, index, inertial_in_prim, articulation.path, body.mass_properties.mass)

    def _initialise_dofs(self, body_id: int, dofs: list) -> tuple["DriveSpec | None", ...]:
        """Initial joint positions and velocities, motors off, limits; the drive of each DOF."""
        p = self.p
        description = self.description
        drives = []
        for index, joint, sign in dofs:
            position = joint.initial_position
            if position is None:
                pose0 = description.bodies[joint.body0].pose if joint.body0 else IDENTITY_POSE
                pose1 = description.bodies[joint.body1].pose if joint.body1 else IDENTITY_POSE
                position = joint_frame_offset(joint, pose0, pose1)
            p.resetJointState(body_id, index, sign * position, sign * joint.initial_velocity)
            p.setJointMotorControl2(body_id, index, p.VELOCITY_CONTROL, force=0.0)
            if math.isfinite(joint.lower) or math.isfinite(joint.upper):
                low, high = sorted((sign * joint.lower, sign * joint.upper))
                p.changeDynamics(body_id, index, jointLowerLimit=max(low, -1e10), jointUpperLimit=min(high, 1e10))
            drives.append(DriveSpec.for_joint(joint))
        return tuple(drives)

    # -- joints between free bodies -------------------------------------------------------
    def _constraint_side(self, body_path: str | None, frame: Pose):
        """(body id, link, frame relative to the link's inertial frame) for one side of a constraint."""
        if body_path is None:
            return -1, -1, frame
        handle = self.scene.bodies[body_path]
        return handle.body_id, handle.link, compose(invert(handle.inertial_in_prim), frame)

    def _build_constraint(self, joint: Joint):
        if joint.kind == "d6":
            if not joint.exclude_from_articulation:
                self._unsupported(joint.path, "a D6 joint that is not a surface-gripper attachment point")
            return
        if not joint.enabled:
            return
        if joint.kind in ("revolute", "prismatic") and (joint.drive is not None or math.isfinite(joint.lower)
                                                         or math.isfinite(joint.upper)):
            self._unsupported(joint.path, "limits and drives of a joint outside an articulation are not simulated")
        p = self.p
        parent_id, parent_link, parent_frame = self._constraint_side(joint.body0, joint.pose0)
        child_id, child_link, child_frame = self._constraint_side(joint.body1, joint.pose1)
        if parent_id == -1:   # PyBullet needs a body as parent; swap sides
            parent_id, parent_link, parent_frame, child_id, child_link, child_frame = (
                child_id, child_link, child_frame, parent_id, parent_link, parent_frame)
        ids = []
        if joint.kind in ("fixed", "prismatic"):
            kind = p.JOINT_FIXED if joint.kind == "fixed" else p.JOINT_PRISMATIC
            axis = list(AXIS_VECTORS[joint.axis]) if joint.kind == "prismatic" else [0.0, 0.0, 0.0]
            ids.append(p.createConstraint(parent_id, parent_link, child_id, child_link, kind, axis,
                                          parentFramePosition=parent_frame[0], childFramePosition=child_frame[0],
                                          parentFrameOrientation=parent_frame[1],
                                          childFrameOrientation=child_frame[1]))
        else:  # spherical: one pin; revolute: two pins on the axis
            offsets = [0.0] if joint.kind == "spherical" else [-REVOLUTE_PIN_HALF_SPAN, REVOLUTE_PIN_HALF_SPAN]
            pin_axis = AXIS_VECTORS[joint.axis]
            for offset in offsets:
                pin = ((pin_axis[0] * offset, pin_axis[1] * offset, pin_axis[2] * offset), (0.0, 0.0, 0.0, 1.0))
                parent_pin, child_pin = compose(parent_frame, pin), compose(child_frame, pin)
                ids.append(p.createConstraint(parent_id, parent_link, child_id, child_link, p.JOINT_POINT2POINT,
                                              [0.0, 0.0, 0.0], parentFramePosition=parent_pin[0],
                                              childFramePosition=child_pin[0]))
        for constraint in ids:
            p.changeConstraint(constraint, maxForce=CONSTRAINT_MAX_FORCE)
        if not joint.collision_enabled and child_id != -1:
            p.setCollisionFilterPair(parent_id, child_id, parent_link, child_link, 0)
        self.scene.constraints[joint.path] = ids


@dataclass
class _Tree:
    """An articulation's base and its joints in link order, while it is being built."""

    root_body: str | None                 # None: a massless anchor base
    fixed_base: bool
    anchor_joint: Joint | None            # the joint to the world, if any
    order: list[tuple[str, Joint, str | None, bool]] = field(default_factory=list)
    visited: set = field(default_factory=set)


@dataclass
class _Links:
    """createMultiBody's arrays and the frames and DOFs that go with them, while being built."""

    link_from_prim: dict                  # body path -> its prim frame in its link frame
    link_index: dict                      # body path -> link index (-1: base)
    arrays: dict = field(default_factory=lambda: {key: [] for key in (
        "masses", "shapes", "visuals", "positions", "orientations", "inertial_positions", "inertial_orientations",
        "parents", "types", "axes")})
    dofs: list = field(default_factory=list)          # (link index, joint, sign) of each movable joint
    base_mass: float = 0.0
    base_inertial: Pose = IDENTITY_POSE


def _body_on_world_joint(joint: Joint) -> str:
    """The body a joint to the world moves (the import refuses a joint with no body on either side)."""
    body = joint.body1 if joint.body0 is None else joint.body0
    if body is None:
        raise ValueError(f"{joint.path} joins no body")
    return body


def _cone_points(shape: Shape):
    """Apex on +axis at half height, base circle at -half height (USD Cone convention)."""
    axis = shape.axis
    points = []
    for i in range(CONE_SEGMENTS):
        angle = 2.0 * math.pi * i / CONE_SEGMENTS
        u, v = shape.radius * math.cos(angle), shape.radius * math.sin(angle)
        points.append(_along(axis, -shape.half_height, u, v))
    points.append(_along(axis, shape.half_height, 0.0, 0.0))
    return points


def _along(axis: str, height: float, u: float, v: float):
    if axis == "X":
        return (height, u, v)
    if axis == "Y":
        return (v, height, u)
    return (u, v, height)
