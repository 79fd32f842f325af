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

``graphflow.usd.resolver.resolve_stage(reference, base_dir=None) -> Path`` (stage names are usd's business)
    ``asset:ur10_pick_place.usda`` names a packaged stage; other references are
    paths, relative to *base_dir* (the graph file's folder).

``PyBulletWorld`` implements ``graphflow.world.World`` (the declared backend interface), plus:
    ``substeps``; ``step()`` = ``substeps`` PyBullet steps, then ``attachments.update``, then the
    services in registration order; ``play()``, ``pause()`` (``step()`` does nothing while paused),
    ``stop()`` (reset and pause), ``reset()`` (rebuild: bit-identical initial state; then resets the
    attachments and the services). ``prim_pose(path)`` serves bodies, colliders, joints (their
    body0-side frame) and any Xformable prim (carried by its nearest body ancestor);
    ``joint_names/joint_paths/joint_positions/joint_velocities(path)`` take the articulation root or
    any body/joint/descendant prim of it (DOFs in tree order, rad or m);
    ``get_attribute/set_attribute(prim, name)`` serve the names in ``ATTRIBUTES`` (the table is the
    dispatch; USD units: degrees for angular drive targets and limits; other authored USD attributes
    are read-only); ``raycast``/``raycast_batch`` -> ``RayHit``; ``contacts(path)`` -> ``Contact``;
    ``apply_force(path, force, position=None)`` (world frame, during the next step only);
    ``body_of``/``same_body``; ``gravity_enabled``/``set_gravity_enabled(prim, enabled)`` (a
    counter-force -m g each step, at the centre of mass); ``set_collision_between(prim_a, prim_b,
    enabled)``; ``attachments`` (``graphflow.world.Attachments``: compliant holds, see
    ``attachment.py``); ``attachment_joints`` ``{joint_path: Joint}`` for D6 joints with
    ``physics:excludeFromArticulation`` (NOT simulated; the gripper's attachment points).
    Unknown prims or attributes raise ``graphflow.world.WorldError`` naming the prim.

Modules: ``world`` (the world, its stepping, node-facing queries), ``builder`` (description ->
PyBullet objects, in named steps; frozen handles), ``drives`` (drive torques/motors and gravity
switches before each substep; ``DriveTargets`` is the run-time drive state), ``attributes`` (the
attribute table), ``lookups`` (prim path -> body, articulation, pose), ``attachment`` (holds),
``recorder`` (video, a world service), ``keyboard`` (the window's keys), ``inspect`` (``graphflow stage``).

Backend-internal API (inside ``graphflow.physics``, and its own tests; never for nodes or the gripper)
=======================================================================================================

``world.client``                 the ``pybullet_utils.bullet_client.BulletClient`` of this world
``world.description``            the parsed ``StageDescription`` (immutable; ``surface_grippers``, ``joints``...)
``world.unsupported``            (path, reason) of every prim not simulated: the import's and the build's
``world.scene``                  the ``BuiltScene`` of the current build (frozen ``BodyHandle``/``ArticulationHandle``)
``world.drive_targets[path]``    ``DriveTargets(positions, velocities, efforts)`` of an articulation (SI units)
``world.masses[path]``           live body masses (``physics:mass`` can be set)
``world.body_link(prim_path)``   ``(body_id, link_index)``; link -1 = base. Colliders resolve to their body.
``world.body_handle(prim_path)`` the ``BodyHandle`` (or None); ``world.prim_at(body_id, link)`` the body prim path
``world.inertial_in_prim(prim)`` the link's inertial frame in the prim frame (PyBullet constraint frames are relative to it)
Anything created through ``world.client`` is gone after ``reset()`` (the client is rebuilt), so users
of the client re-create it from a ``reset()`` hook or lazily.

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
  ``world.unsupported`` (the import's alone in ``description.unsupported``).
* Articulation self-collision follows ``physxArticulation:enabledSelfCollisions`` (default off).
"""
from __future__ import annotations

from graphflow.physics.native_output import native_output_silenced
from graphflow.usd.errors import StageError, UnsupportedPrimWarning
from graphflow.usd.resolver import resolve_stage

with native_output_silenced(1, 2):
    import pybullet  # noqa: F401  (imported here once so its build banner never reaches the output)

__all__ = ["create_world", "StageError", "UnsupportedPrimWarning",
           "PyBulletWorld", "RayHit", "Contact", "ATTRIBUTES"]


def create_world(stage=None, *, time_step: float | None = None, substeps: int | None = None, gui: bool = False,
                 description=None):
    """Load a stage (path or ``Usd.Stage``; None = empty world) into a new PyBullet world.

    *description*: the open stage's ``StageDescription`` when it was parsed already (not parsed again).
    """
    from graphflow.physics.world import PyBulletWorld
    from graphflow.usd.description import StageDescription
    from graphflow.usd.physics_import import load_description, open_stage

    if stage is None:
        description = StageDescription(source="<empty world>", up_axis="Z", meters_per_unit=1.0,
                                       gravity=(0.0, 0.0, -9.81), time_step=None)
        return PyBulletWorld(description, None, time_step=time_step, substeps=substeps, gui=gui)
    if isinstance(stage, str) and stage.startswith("asset:"):
        stage = resolve_stage(stage)
    usd_stage, _label = open_stage(stage)
    if description is None:
        description = load_description(usd_stage)
    return PyBulletWorld(description, usd_stage, time_step=time_step, substeps=substeps, gui=gui)


def __getattr__(name):
    if name in ("RayHit", "Contact"):
        import graphflow.world

        return getattr(graphflow.world, name)
    if name in ("PyBulletWorld", "ATTRIBUTES"):
        from graphflow.physics import world

        return getattr(world, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
