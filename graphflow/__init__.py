"""graphflow: OmniGraph-style action graphs for robot manipulation, on PyBullet."""

__version__ = "0.1.0"
