"""Isaac asset URLs opened from a local folder: a remap table (and a download cache) applied when a stage is opened.

Isaac-authored stages name NVIDIA's assets by URL (``https://omniverse-content-production...``,
``omniverse://...``). The table maps URL prefixes to local folders; it comes from the nearest
``graphflow.toml`` (this folder or a parent)::

    [assets.remap]
    "https://omniverse-content-production.s3-us-west-2.amazonaws.com/Assets/Isaac/4.5" = "/data/isaac"

and from ``GRAPHFLOW_ASSET_REMAP`` (``PREFIX=FOLDER`` entries separated by ``;``; it wins over the
file). The user's files are never edited: a layer naming a remapped asset, directly or through
the local layers it opens, is read into an in-memory copy whose asset paths
``UsdUtils.ModifyAssetPaths`` rewrites (relative ones made absolute, so they still find their
files), and the stage opens that copy. ``http(s)`` assets no prefix covers can be fetched into a
download cache (``graphflow.usd.downloads``).
"""
from __future__ import annotations

import os
import sys
from dataclasses import dataclass, field
from pathlib import Path

from graphflow.usd.errors import StageError

ENVIRONMENT_VARIABLE = "GRAPHFLOW_ASSET_REMAP"
PROJECT_FILE = "graphflow.toml"


@dataclass(frozen=True)
class RemapTable:
    """URL prefix -> local folder, longest prefix first."""

    entries: tuple[tuple[str, str], ...] = ()
    sources: tuple[str, ...] = field(default=(), compare=False)   # where the entries came from, for messages

    def apply(self, asset: str) -> str | None:
        """The local path *asset* maps to, or None when no prefix matches."""
        for prefix, folder in self.entries:
            if asset.startswith(prefix):
                rest = asset[len(prefix):].lstrip("/")
                return str(Path(folder) / rest) if rest else folder
        return None

    def __bool__(self) -> bool:
        return bool(self.entries)


def remap_table(start: str | os.PathLike | None = None) -> RemapTable:
    """The table in force: the environment variable's entries, then the nearest graphflow.toml's."""
    entries: dict[str, str] = {}
    sources = []
    project = _project_file(Path(start) if start is not None else Path.cwd())
    if project is not None:
        entries.update(_file_entries(project))
        sources.append(str(project))
    text = os.environ.get(ENVIRONMENT_VARIABLE, "")
    for item in filter(None, (part.strip() for part in text.split(";"))):
        prefix, equals, folder = item.partition("=")
        if not equals or not prefix or not folder:
            raise StageError(f"{ENVIRONMENT_VARIABLE}: {item!r} is not PREFIX=FOLDER")
        entries[prefix] = str(Path(folder).expanduser().resolve())
        sources.append(ENVIRONMENT_VARIABLE)
    ordered = tuple(sorted(entries.items(), key=lambda item: -len(item[0])))
    return RemapTable(ordered, tuple(sources))


def project_folder_setting(start: str | os.PathLike, name: str) -> Path | None:
    """A folder under ``[assets]`` in the nearest graphflow.toml, relative to that file (None when absent)."""
    project = _project_file(Path(start))
    if project is None:
        return None
    value = _read(project).get("assets", {}).get(name)
    if value is None:
        return None
    if not isinstance(value, str):
        raise StageError(f"{project}: [assets] {name} must be a folder string")
    return (project.parent / Path(value).expanduser()).resolve()


def _project_file(folder: Path) -> Path | None:
    for candidate in (folder.resolve(), *folder.resolve().parents):
        if (candidate / PROJECT_FILE).is_file():
            return candidate / PROJECT_FILE
    return None


def _read(path: Path) -> dict:
    if sys.version_info >= (3, 11):
        import tomllib
    else:   # pragma: no cover - Python 3.10
        import tomli as tomllib
    try:
        return tomllib.loads(path.read_text(encoding="utf-8"))
    except (OSError, UnicodeDecodeError, tomllib.TOMLDecodeError) as error:
        raise StageError(f"{path}: {' '.join(str(error).split())}") from None


def _file_entries(path: Path) -> dict[str, str]:
    table = _read(path).get("assets", {}).get("remap", {})
    if not isinstance(table, dict) or not all(isinstance(v, str) for v in table.values()):
        raise StageError(f"{path}: [assets.remap] must map URL prefixes to folder strings")
    return {prefix: str((path.parent / Path(folder).expanduser()).resolve()) for prefix, folder in table.items()}


class RemappedLayers:
    """In-memory copies of the layers that name remapped assets (kept alive while the stage is open)."""

    def __init__(self, table: RemapTable, cache=None):
        self.table = table
        self.cache = cache   # graphflow.usd.downloads.DownloadCache, or None: URLs stay as written
        self.copies: dict[str, object] = {}    # real path -> anonymous Sdf.Layer (or None: needs no copy)

    def root(self, path: str):
        """The anonymous copy of the layer at *path*, or None when nothing in it (or below it) is remapped."""
        from pxr import Sdf, UsdUtils

        real = str(Path(path).resolve())
        if real in self.copies:
            return self.copies[real]
        self.copies[real] = None   # a cycle of layers ends here
        original = Sdf.Layer.FindOrOpen(real)
        if original is None:
            return None
        changed = False

        def modify(asset: str) -> str:
            nonlocal changed
            if not asset:
                return asset
            local = self.table.apply(asset)
            if local is None and self.cache is not None:
                if asset.startswith(("http://", "https://")):
                    local = self.cache.fetch(asset)
                elif "://" not in asset and not Path(asset).is_absolute():
                    local = self.cache.relative(real, asset)   # beside a fetched layer: fetched too
            if local is not None:
                changed = True
                return self._copied(local) or local
            if "://" in asset or Path(asset).is_absolute() or not asset.startswith((".", "/")) and \
                    not Path(original.ComputeAbsolutePath(asset)).exists():
                return asset   # URLs, absolute paths and search paths (graphflow/ur10.usda) as written
            absolute = original.ComputeAbsolutePath(asset)
            copied = self._copied(absolute)
            changed = changed or copied is not None
            return copied or absolute

        copy = Sdf.Layer.CreateAnonymous(Path(real).name)
        copy.TransferContent(original)
        UsdUtils.ModifyAssetPaths(copy, modify)
        self.copies[real] = copy if changed else None
        return self.copies[real]

    def _copied(self, path: str) -> str | None:
        """The identifier of a copy of the local layer at *path* when it needs one."""
        if not Path(path).is_file():
            return None
        layer = self.root(path)
        return layer.identifier if layer is not None else None
