"""Finding stages: packaged assets (``asset:NAME``) and paths relative to a graph file."""
from __future__ import annotations

import os
from pathlib import Path

from graphflow.usd.errors import StageError

ASSET_PREFIX = "asset:"
ASSET_DIRECTORY = Path(__file__).resolve().parent.parent / "assets"


def asset_path(name: str) -> Path:
    """Path of a stage shipped in ``graphflow/assets`` (e.g. ``"ur10_pick_place.usda"``)."""
    path = ASSET_DIRECTORY / name
    if not path.is_file():
        available = ", ".join(sorted(p.name for p in ASSET_DIRECTORY.glob("*.usd*")))
        raise StageError(f"{ASSET_PREFIX}{name}: no such packaged asset (available: {available})")
    return path


def resolve_stage(reference: str, base_dir: str | os.PathLike | None = None) -> Path:
    """Turn a graph document's stage value into a file path.

    ``asset:NAME`` names a packaged asset; anything else is a path, relative
    paths being taken from *base_dir* (the graph file's folder).
    """
    if reference.startswith(ASSET_PREFIX):
        return asset_path(reference[len(ASSET_PREFIX):])
    path = Path(reference).expanduser()
    if not path.is_absolute() and base_dir is not None:
        path = Path(base_dir) / path
    return path
