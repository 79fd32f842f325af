"""``GripperView``: Isaac's batched view over several surface grippers (``gripper_view.py``)."""
from __future__ import annotations

from typing import Sequence

from graphflow.gripper.manager import SurfaceGripperManager


class GripperView:
    """Grippers addressed by index, as Isaac's ``GripperView(paths, ...)``.

    Every per-gripper list must have one value per gripper (``ValueError``
    otherwise); with *indices* only those grippers take their value.
    """

    def __init__(self, manager: SurfaceGripperManager, paths: Sequence[str], *, max_grip_distance=None,
                 coaxial_force_limit=None, shear_force_limit=None, retry_interval=None):
        self.manager = manager
        self.paths = list(paths)
        for path in self.paths:
            manager.component(path)       # fail early on a path that is not a gripper
        self.set_surface_gripper_properties(max_grip_distance=max_grip_distance,
                                            coaxial_force_limit=coaxial_force_limit,
                                            shear_force_limit=shear_force_limit, retry_interval=retry_interval)

    @property
    def count(self) -> int:
        return len(self.paths)

    def _selected(self, values, indices, name):
        if len(values) != self.count:
            raise ValueError(f"{name} needs {self.count} values (one per gripper), got {len(values)}")
        return range(self.count) if indices is None else list(indices)

    def apply_gripper_action(self, values: Sequence[float], indices: Sequence[int] | None = None) -> None:
        for index in self._selected(values, indices, "values"):
            self.manager.set_gripper_action(self.paths[index], values[index])

    def get_surface_gripper_status(self) -> list[str]:
        return [status.token for status in self.manager.get_gripper_status_batch(self.paths)]

    def get_gripped_objects(self) -> list[list[str]]:
        return self.manager.get_gripped_objects_batch(self.paths)

    def set_surface_gripper_properties(self, max_grip_distance=None, coaxial_force_limit=None,
                                       shear_force_limit=None, retry_interval=None,
                                       indices: Sequence[int] | None = None) -> None:
        given = {"max_grip_distance": max_grip_distance, "coaxial_force_limit": coaxial_force_limit,
                 "shear_force_limit": shear_force_limit, "retry_interval": retry_interval}
        for name, values in given.items():
            if values is None:
                continue
            for index in self._selected(values, indices, name):
                self.manager.set_gripper_properties(self.paths[index], **{name: values[index]})

    def get_surface_gripper_properties(self) -> tuple[list[float], list[float], list[float], list[float]]:
        """``(maxGripDistance, coaxialForceLimit, shearForceLimit, retryInterval)``, one list each."""
        rows = [self.manager.get_gripper_properties(path) for path in self.paths]
        distance, coaxial, shear, retry = ([row[column] for row in rows] for column in range(4))
        return distance, coaxial, shear, retry
