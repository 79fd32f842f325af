"""``get_attribute``/``set_attribute`` of ``PyBulletWorld``: the table of live attributes is the dispatch.

Each entry of ``ATTRIBUTES`` names a USD attribute the world simulates, says
what it is (its ``doc``, "RW" or "R ") and holds the functions that read and
(if writable) write it, in USD units: degrees for angular joint values, the
parent prim's frame for body poses and velocities. Any other authored USD
attribute is read from the stage and is read-only.
"""
from __future__ import annotations

import math
from typing import Any, Callable, NamedTuple

from graphflow.poses import compose, invert, quat_rotate, relative
from graphflow.usd.stage_edits import plain
from graphflow.world import WorldError

_DEGREES = 180.0 / math.pi


class AttributeAccess(NamedTuple):
    doc: str
    get: Callable[[Any, str, str], Any]                        # (world, prim path, name) -> value
    set: Callable[[Any, str, str, Any], None] | None = None     # (world, prim path, name, value); None: read-only


# -- joints ------------------------------------------------------------------------------------------

def _joint_dof(world, prim_path: str, name: str):
    location = world.scene.joint_dofs.get(prim_path)
    if location is None:
        raise WorldError(f"{prim_path} has no attribute {name}: it is not a driven articulation joint")
    return world.scene.articulations[location[0]], location[1]


def _unit(world, prim_path: str, name: str) -> float:
    """Scale from SI to the USD value of a joint attribute (degrees for angular joints)."""
    joint = world.description.joints[prim_path]
    angular = joint.kind == "revolute"
    family = "angular" if ":angular:" in name else "linear" if ":linear:" in name else None
    if family is not None and family != ("angular" if angular else "linear"):
        raise WorldError(f"{prim_path} is a {joint.kind} joint: it has no attribute {name}")
    return _DEGREES if angular else 1.0


def _drive_target(world, prim_path: str, name: str):
    """(articulation targets, DOF, SI -> USD scale) of a drive-target attribute, checked."""
    articulation, dof = _joint_dof(world, prim_path, name)
    scale = _unit(world, prim_path, name)
    if articulation.drives[dof] is None:
        raise WorldError(f"{prim_path} has no drive, so no attribute {name}")
    return world.drive_targets[articulation.path], dof, scale


def _get_target_position(world, prim_path, name):
    targets, dof, scale = _drive_target(world, prim_path, name)
    return targets.positions[dof] * scale


def _set_target_position(world, prim_path, name, value):
    targets, dof, scale = _drive_target(world, prim_path, name)
    targets.positions[dof] = float(value) / scale


def _get_target_velocity(world, prim_path, name):
    targets, dof, scale = _drive_target(world, prim_path, name)
    return targets.velocities[dof] * scale


def _set_target_velocity(world, prim_path, name, value):
    targets, dof, scale = _drive_target(world, prim_path, name)
    targets.velocities[dof] = float(value) / scale


def _get_joint_position(world, prim_path, name):
    articulation, dof = _joint_dof(world, prim_path, name)
    return world.joint_positions(articulation.path)[dof] * _unit(world, prim_path, name)


def _get_joint_velocity(world, prim_path, name):
    articulation, dof = _joint_dof(world, prim_path, name)
    return world.joint_velocities(articulation.path)[dof] * _unit(world, prim_path, name)


def _get_limit(world, prim_path, name):
    joint = world.description.joints.get(prim_path)
    if joint is None or joint.kind not in ("revolute", "prismatic"):
        raise WorldError(f"{prim_path} has no attribute {name}: it is not a revolute or prismatic joint")
    value = joint.lower if name == "physics:lowerLimit" else joint.upper
    return value * (_DEGREES if joint.kind == "revolute" else 1.0)


# -- bodies ------------------------------------------------------------------------------------------

def _body(world, prim_path: str, name: str, writing: bool = False):
    handle = world.scene.bodies.get(prim_path)
    if handle is None:
        if writing:
            raise WorldError(f"{prim_path} has no writable attribute {name}: it is not a rigid body")
        raise WorldError(f"{prim_path} has no attribute {name}: it is not a rigid body")
    return handle


def _free_body(world, prim_path: str, name: str):
    handle = _body(world, prim_path, name, writing=True)
    if handle.link != -1:
        raise WorldError(f"{handle.path}: {name} can only be written on a free body or an articulation root")
    return handle


def _get_local_pose(world, prim_path, name):
    if prim_path not in world.scene.bodies:     # not simulated: as composed (an animation may have moved it)
        return _get_usd_attribute(world, prim_path, name)
    handle = _body(world, prim_path, name)
    local = relative(world._parent_pose(prim_path), world._body_pose(handle))
    return local[0] if name == "xformOp:translate" else local[1]


def _set_local_pose(world, prim_path, name, value):
    handle = _free_body(world, prim_path, name)
    vector = tuple(float(c) for c in value)
    parent = world._parent_pose(handle.path)
    local = relative(parent, world._body_pose(handle))
    local = (vector, local[1]) if name == "xformOp:translate" else (local[0], vector)
    target = compose(compose(parent, local), handle.inertial_in_prim)
    world.client.resetBasePositionAndOrientation(handle.body_id, target[0], target[1])


def _get_mass(world, prim_path, name):
    return world.masses[_body(world, prim_path, name).path]


def _set_mass(world, prim_path, name, value):
    handle = _body(world, prim_path, name, writing=True)
    if handle.kind != "dynamic":
        raise WorldError(f"{handle.path}: physics:mass can only be set on a dynamic body")
    mass = float(value)
    if not mass > 0:
        raise WorldError(f"{handle.path}: physics:mass must be positive, got {value}")
    client = world.client
    inertia = client.getDynamicsInfo(handle.body_id, handle.link)[2]
    client.changeDynamics(handle.body_id, handle.link, mass=mass,
                          localInertiaDiagonal=[c * mass / world.masses[handle.path] for c in inertia])
    world.masses[handle.path] = mass
    world.gravity_switches.masses_changed()


def _get_velocity(world, prim_path, name):
    _body(world, prim_path, name)
    linear, angular = world.prim_velocity(prim_path)
    inverse = invert(((0.0, 0.0, 0.0), world._parent_rotation(prim_path)))[1]
    if name == "physics:velocity":
        return quat_rotate(inverse, linear)
    return tuple(c * _DEGREES for c in quat_rotate(inverse, angular))


def _set_velocity(world, prim_path, name, value):
    handle = _free_body(world, prim_path, name)
    vector = tuple(float(c) for c in value)
    rotation = world._parent_rotation(handle.path)
    linear, angular = world.client.getBaseVelocity(handle.body_id)
    if name == "physics:velocity":
        linear = quat_rotate(rotation, vector)
    else:
        angular = quat_rotate(rotation, tuple(c * math.pi / 180.0 for c in vector))
    world.client.resetBaseVelocity(handle.body_id, linear, angular)


# Attributes nodes may read (R) or write (W); anything else authored on the stage is read-only from USD.
ATTRIBUTES: dict[str, AttributeAccess] = {
    "drive:linear:physics:targetPosition": AttributeAccess(
        "RW prismatic joint drive target, m", _get_target_position, _set_target_position),
    "drive:angular:physics:targetPosition": AttributeAccess(
        "RW revolute joint drive target, degrees (as USD)", _get_target_position, _set_target_position),
    "drive:linear:physics:targetVelocity": AttributeAccess(
        "RW prismatic joint drive target velocity, m/s", _get_target_velocity, _set_target_velocity),
    "drive:angular:physics:targetVelocity": AttributeAccess(
        "RW revolute joint drive target velocity, degrees/s", _get_target_velocity, _set_target_velocity),
    "state:linear:physics:position": AttributeAccess("R  prismatic joint position, m", _get_joint_position),
    "state:angular:physics:position": AttributeAccess("R  revolute joint position, degrees", _get_joint_position),
    "state:linear:physics:velocity": AttributeAccess("R  prismatic joint velocity, m/s", _get_joint_velocity),
    "state:angular:physics:velocity": AttributeAccess("R  revolute joint velocity, degrees/s", _get_joint_velocity),
    "physics:lowerLimit": AttributeAccess("R  joint lower limit (m or degrees, as USD)", _get_limit),
    "physics:upperLimit": AttributeAccess("R  joint upper limit (m or degrees, as USD)", _get_limit),
    "xformOp:translate": AttributeAccess(
        "RW body position in its parent prim's frame, m (writing teleports the body)", _get_local_pose,
        _set_local_pose),
    "xformOp:orient": AttributeAccess(
        "RW body orientation in its parent prim's frame, quaternion (x, y, z, w)", _get_local_pose, _set_local_pose),
    "physics:mass": AttributeAccess("RW body mass, kg", _get_mass, _set_mass),
    "physics:velocity": AttributeAccess(
        "RW body linear velocity in its parent prim's frame, m/s", _get_velocity, _set_velocity),
    "physics:angularVelocity": AttributeAccess(
        "RW body angular velocity in its parent prim's frame, degrees/s (as USD)", _get_velocity, _set_velocity),
}


def get_attribute(world, prim_path: str, name: str):
    access = ATTRIBUTES.get(name)
    if access is None:
        return _get_usd_attribute(world, prim_path, name)
    return access.get(world, prim_path, name)


def set_attribute(world, prim_path: str, name: str, value) -> None:
    """What physics simulates goes to the simulation (``ATTRIBUTES``); any other attribute the stage has (a
    custom one, a light's, a plain prim's xform op) is written to the run's stage-edit layer, which refuses
    a value that would change what is simulated (a collider's size): physics is composed once, at load."""
    access = ATTRIBUTES.get(name)
    if access is None or (name in _XFORM_OPS and world.body_of(prim_path) is None):
        world.write_stage_values(prim_path, {f"{prim_path}.{name}": value}, what=f"writing {name}")
        return
    if access.set is None:
        raise WorldError(f"{prim_path}: attribute {name} is read-only")
    access.set(world, prim_path, name, value)


_XFORM_OPS = ("xformOp:translate", "xformOp:orient")   # a body's are simulated; a plain prim's are the stage's


def read_prim(world, prim_path: str, bounding_box: bool = False, time: float | None = None):
    """The prim's bundle: USD's composed values, with the simulated ones (``ATTRIBUTES``) read live."""
    prim = world.stage.GetPrimAtPath(prim_path) if world.stage is not None and prim_path.startswith("/") else None
    if not prim:
        raise WorldError(f"no prim {prim_path} on this stage")

    def live(name: str):
        if name not in ATTRIBUTES:
            return None
        try:
            return ATTRIBUTES[name].get(world, prim_path, name)
        except WorldError:     # not simulated on this prim (a joint attribute on a body, ...): USD's value
            return None

    try:
        pose = world.prim_pose(prim_path)
    except WorldError:       # not placed in space (a scope, a material): no worldMatrix from physics
        pose = None
    return world.prim_reader.read(prim, live=live, world_pose=pose, bounding_box=bounding_box, time=time)


def _get_usd_attribute(world, prim_path: str, name: str):
    if world.stage is not None:
        prim = world.stage.GetPrimAtPath(prim_path)
        if prim:
            attribute = prim.GetAttribute(name)
            if attribute and attribute.HasValue():
                return plain(attribute.Get())
            raise WorldError(f"{prim_path} has no attribute {name}")
    raise WorldError(f"no prim {prim_path} on this stage")
