"""USD side of graphflow: reading physics stages into plain data (usd-core / ``pxr``).

* ``physics_import.load_description(stage_or_path) -> StageDescription``: the
  physics of a stage in SI units, parsed with ``UsdPhysics.LoadUsdPhysicsFromRange``;
* ``description``: the dataclasses it returns (no pxr, no pybullet); poses are
  ``graphflow.poses`` (graphflow's (x, y, z, w) quaternions);
* ``errors``: ``StageError`` (also ``graphflow.physics.StageError``) and
  ``UnsupportedPrimWarning``.

``pxr`` is only imported inside functions, so importing this package is cheap.
"""
from graphflow.usd.errors import StageError, UnsupportedPrimWarning

__all__ = ["StageError", "UnsupportedPrimWarning"]
