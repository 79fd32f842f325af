"""Finding stages: packaged assets (``asset:NAME``, ``graphflow/NAME``, ``@pkg/NAME@``) and paths relative to a graph file."""
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
    paths being taken from *base_dir* (the graph file's folder). As in USD (``@...@`` is accepted),
    a relative path that is not there is looked up in the asset roots: ``graphflow/ur10.usda``.
    """
    from graphflow.usd.asset_roots import root_file

    reference = reference[1:-1] if len(reference) > 2 and reference[0] == reference[-1] == "@" else reference
    if reference.startswith(ASSET_PREFIX):
        return asset_path(reference[len(ASSET_PREFIX):])
    path = Path(reference).expanduser()
    if not path.is_absolute() and base_dir is not None:
        path = Path(base_dir) / path
    if not path.exists() and not Path(reference).is_absolute():
        return root_file(reference) or path
    return path
