"""Isaac Sim's surface gripper on graphflow: USD schema, runtime manager, legacy tutorial class.

* ``manager_for(world)`` -> the world's ``SurfaceGripperManager`` (Isaac's
  interface: ``open_gripper``, ``close_gripper``, ``set_gripper_action``,
  ``get_gripper_status``, ``get_gripped_objects``, ``*_batch``,
  ``set_write_to_usd``, plus ``set_gripper_properties``/``get_gripper_properties``).
* ``create_surface_gripper(stage, parent_path)``, ``define_surface_gripper``,
  ``apply_attachment_point_api``, ``register_schema``: the USD side.
* ``GripperStatus`` (Open=0, Closing=1, Closed=2).
* ``SurfaceGripper``: the legacy ``translate/direction/...`` gripper of Isaac's tutorials.
"""
from graphflow.gripper.component import GripperStatus
from graphflow.gripper.manager import SurfaceGripperManager, manager_for
from graphflow.gripper.usd_schema import (
                         apply_attachment_point_api,
                         create_surface_gripper,
                         define_surface_gripper,
                         register_schema,
)

__all__ = ["GripperStatus", "SurfaceGripperManager", "apply_attachment_point_api", "create_surface_gripper",
           "define_surface_gripper", "manager_for", "register_schema"]
