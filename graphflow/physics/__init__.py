"""graphflow's physics backend: a ``World`` on PyBullet, loaded from USD stages.

This is the only package that imports ``pybullet``; it is imported lazily, so
``import graphflow.physics`` stays cheap until a world is created.

Public API
==========

``create_world(stage=None, *, time_step=None, substeps=None, gui=False) -> PyBulletWorld``
    *stage*: a ``.usd``/``.usda`` path, ``asset:NAME`` (a packaged stage), an
    open ``Usd.Stage``, or None for an empty world with default gravity. *time_step* None = the stage's PhysicsScene
    ``physxScene:timeStepsPerSecond`` if authored, else 1/60 s (Isaac Sim's
    default). *substeps* None = enough PyBullet steps per stage step that each is at most
    1/240 s (4 at 60 Hz: see ``graphflow.physics.contacts``). A world is a context manager;
    ``close()`` frees its client.
    A broken stage raises ``StageError`` (a ``ValueError``) naming file and prim.

``resolve_stage(reference, base_dir=None) -> Path`` / ``asset_path(name) -> Path``
    ``asset:ur10_pick_place.usda`` names a packaged stage; other references are
    paths, relative to *base_dir* (the graph file's folder).

``PyBulletWorld`` (``graphflow.world.World`` plus):
    ``time_step``, ``time``, ``step_index``; ``step()`` = ``substeps`` PyBullet
    steps then the post-step services in registration order; ``play()``,
    ``pause()`` (``step()`` does nothing while paused), ``stop()`` (reset and
    pause), ``reset()`` (rebuild: bit-identical initial state; then calls
    ``service.reset()`` on every post-step service that has one).
    ``prim_pose(path) -> ((x, y, z), (qx, qy, qz, qw))`` for bodies, colliders,
    joints (their body0-side frame) and any Xformable prim (carried by its
    nearest body ancestor); ``prim_velocity(path) -> (linear, angular rad/s)``;
    ``joint_names/joint_paths/joint_positions/joint_velocities(path)`` where
    *path* is the articulation root or any body/joint/descendant prim of it
    (DOFs in tree order, rad or m); ``set_joint_targets(path, indices, *,
    positions=, velocities=, efforts=)``; ``get_attribute/set_attribute(prim,
    name)`` for the names in ``ATTRIBUTES`` (USD units: degrees for angular
    drive targets and limits; other authored USD attributes are read-only);
    ``raycast(origin, direction, length) -> RayHit(prim_path, position, normal,
    distance) | None``; ``raycast_batch(origins, directions, length)``;
    ``contacts(path) -> [Contact(other_prim, position, normal, distance,
    normal_force)]``; ``apply_force(path, force, position=None)`` (world frame,
    during the next step only). Unknown prims or attributes raise
    ``graphflow.world.WorldError`` naming the prim.

Backend-internal API (for the surface gripper)
==============================================

``world.client``                 the ``pybullet_utils.bullet_client.BulletClient`` of this world
``world.stage``                  the ``Usd.Stage`` (None for an empty world)
``world.body_link(prim_path)``   ``(body_id, link_index)``; link -1 = base. Colliders resolve to their body.
``world.prim_at(body_id, link)`` the rigid-body prim path, or None (e.g. a gripper's own helper body)
``world.attachment_joints``      ``{joint_path: Joint}`` for D6 joints with ``physics:excludeFromArticulation``;
                                 they are NOT simulated. ``Joint`` (``graphflow.usd.description``) has
                                 ``body0``/``body1`` (prim path or None), ``pose0``/``pose1`` = (localPos, localRot
                                 as xyzw) in metres, ``limits`` {"transX".."rotZ": AxisLimit(low, high)} (rot in
                                 radians; low > high = locked), ``drives`` {axis: Drive(stiffness, damping,
                                 max_force, target_position, target_velocity, acceleration)} (rot per radian),
                                 ``enabled``, ``break_force``, ``break_torque``.
``world.description``            the whole parsed ``StageDescription`` (``surface_grippers``: path + attachment points)
``world.set_collision_between(prim_a, prim_b, enabled)``
``world.set_gravity_enabled(prim_path, enabled)``  (a counter-force m*g each step, at the centre of mass)
PyBullet constraint frames are relative to a link's inertial frame; ``world.inertial_in_prim(prim)`` gives
that frame in the prim frame. Anything created through ``world.client`` is gone after ``reset()``
(the client is rebuilt), so services re-create it from their ``reset()`` hook or lazily.

Choices
=======

* Drives are PhysX's implicit PD drive computed once per stage step with the joints' gravity
  load and feed-forward efforts (``drive_law``): joint torques, or for a drive far stiffer than
  its link a velocity motor solved with the contacts. A joint that a step would carry past a
  limit is stopped on it by a rigid motor. See docs/physics.md.
* Contacts (``contacts``): PyBullet steps of at most 1/240 s (4 per 60 Hz stage step unless
  ``substeps`` is given), a friction anchor on every dynamic body, a ``UsdGeom.Plane`` collider
  as a large static box.
* A non-finite body pose or velocity after a step raises ``health.NonFiniteState`` naming the
  body and the step.
* Initial joint positions: ``state:{angular,linear}:physics:position`` (PhysX
  JointStateAPI, degrees for angular) if authored, else taken from the bodies'
  authored poses. Link poses follow from the root pose by forward kinematics.
* Authored body velocities (``physics:velocity``, ``physics:angularVelocity``) are the initial velocities.
* Unsupported prims: one ``UnsupportedPrimWarning`` (``warnings``) per prim, also listed in
  ``world.description.unsupported``.
* Articulation self-collision follows ``physxArticulation:enabledSelfCollisions`` (default off).
"""
from __future__ import annotations

from graphflow.usd.errors import StageError, UnsupportedPrimWarning

from .assets import asset_path, resolve_stage
from .native_output import native_output_silenced

with native_output_silenced(1, 2):
    import pybullet  # noqa: F401  (imported here once so its build banner never reaches the output)

__all__ = ["create_world", "StageError", "UnsupportedPrimWarning", "asset_path", "resolve_stage",
           "PyBulletWorld", "RayHit", "Contact", "ATTRIBUTES"]


def create_world(stage=None, *, time_step: float | None = None, substeps: int | None = None, gui: bool = False):
    """Load a stage (path or ``Usd.Stage``; None = empty world) into a new PyBullet world."""
    from graphflow.usd.description import StageDescription
    from graphflow.usd.physics_import import load_description, open_stage

    from .world import PyBulletWorld

    if stage is None:
        description = StageDescription(source="<empty world>", up_axis="Z", meters_per_unit=1.0,
                                       gravity=(0.0, 0.0, -9.81), time_step=None)
        return PyBulletWorld(description, None, time_step=time_step, substeps=substeps, gui=gui)
    if isinstance(stage, str) and stage.startswith("asset:"):
        stage = resolve_stage(stage)
    usd_stage, _label = open_stage(stage)
    return PyBulletWorld(load_description(usd_stage), usd_stage, time_step=time_step, substeps=substeps, gui=gui)


def __getattr__(name):
    if name in ("PyBulletWorld", "RayHit", "Contact", "ATTRIBUTES"):
        from . import world

        return getattr(world, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
