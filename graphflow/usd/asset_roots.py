"""Packaged assets resolved by USD itself: ``@graphflow/ur10.usda@`` composes in any stage.

An asset root is a folder of USD files under a name: graphflow's own is ``graphflow`` (the
packaged ``graphflow/assets``), and installed packages add theirs with an entry point in the group
``graphflow.assets`` (``name = "package.module"``: the folder of that module or package, or a
callable returning a folder). USD's default resolver (``Ar``) looks a search path such as
``graphflow/ur10.usda`` up next to the layer that names it first, then in its search-path
folders; graphflow puts one folder there whose entries are links, one per root, named by the
root. So the composition is USD's own, no C++ resolver plug-in, and a stage that names
``@graphflow/ur10.usda@`` opens the same from any working directory.
"""
from __future__ import annotations

import atexit
import logging
import os
import shutil
import tempfile
from functools import lru_cache
from importlib.metadata import entry_points
from pathlib import Path
from types import ModuleType

from graphflow.usd.errors import StageError

ENTRY_POINT_GROUP = "graphflow.assets"
OWN_ROOT = "graphflow"
OWN_DIRECTORY = Path(__file__).resolve().parent.parent / "assets"
log = logging.getLogger(__name__)


@lru_cache(maxsize=1)
def asset_roots() -> dict[str, Path]:
    """Every asset root by name: graphflow's, then the installed packages' (a broken one is a warning)."""
    roots = {OWN_ROOT: OWN_DIRECTORY}
    for entry_point in sorted(entry_points(group=ENTRY_POINT_GROUP), key=lambda e: e.name):
        try:
            folder = _folder_of(entry_point.load())
        except Exception as error:   # one broken package must not hide the others' assets
            log.warning("asset root %s (%s) skipped: %s", entry_point.name, entry_point.value,
                        " ".join(f"{type(error).__name__}: {error}".split()))
            continue
        if entry_point.name in roots:
            log.warning("asset root %s (%s) skipped: the name is taken by %s", entry_point.name,
                        entry_point.value, roots[entry_point.name])
        elif not folder.is_dir():
            log.warning("asset root %s (%s) skipped: %s is not a folder", entry_point.name, entry_point.value, folder)
        else:
            roots[entry_point.name] = folder
    return roots


def _folder_of(loaded) -> Path:
    if callable(loaded) and not isinstance(loaded, ModuleType):
        loaded = loaded()
    if isinstance(loaded, ModuleType):
        paths = list(getattr(loaded, "__path__", []))
        if paths:
            return Path(paths[0])
        file = getattr(loaded, "__file__", None)      # a built-in module has none
        if file is None:
            raise StageError(f"module {loaded.__name__} has no file, so no folder of assets")
        return Path(file).parent
    return Path(os.fspath(loaded))


def root_file(asset: str) -> Path | None:
    """The file a search path like ``graphflow/ur10.usda`` names in a registered root, or None."""
    name, _, rest = asset.replace("\\", "/").partition("/")
    root = asset_roots().get(name)
    if root is None or not rest:
        return None
    path = root / rest
    return path if path.is_file() else None


@lru_cache(maxsize=1)
def search_folder() -> Path:
    """A folder of links, one per root (removed when the process ends): the search path USD is given."""
    folder = Path(tempfile.mkdtemp(prefix="graphflow-asset-roots-"))
    atexit.register(_remove, folder, os.getpid())
    link_roots(folder)
    return folder


def link_roots(folder: Path, *, force: bool = False) -> list[Path]:
    """Put a link per asset root in *folder* (made if missing): a search path other USD tools can use too.

    An entry already there is replaced only when it is a link, or with *force*.
    """
    folder.mkdir(parents=True, exist_ok=True)
    made = []
    for name, root in asset_roots().items():
        entry = folder / name
        if entry.is_symlink() or (force and entry.exists()):
            shutil.rmtree(entry) if entry.is_dir() and not entry.is_symlink() else entry.unlink()
        elif entry.exists():
            raise StageError(f"{entry}: exists and is not a link; not replacing it (use --force)")
        try:
            entry.symlink_to(root, target_is_directory=True)
        except OSError as error:   # no links on this file system: copy the (small, text) assets instead
            log.debug("asset root %s copied, not linked: %s", name, error)
            shutil.copytree(root, entry)
        made.append(entry)
    return made


def _remove(folder: Path, owner: int) -> None:
    """Remove the links' folder at exit, in the process that made it only (a forked worker shares it)."""
    if os.getpid() == owner:
        shutil.rmtree(folder, ignore_errors=True)


@lru_cache(maxsize=1)
def install_search_path() -> None:
    """Give USD's default resolver the roots (before any graphflow stage is opened), after the user's own
    PXR_AR_DEFAULT_SEARCH_PATH folders."""
    from pxr import Ar

    own = [p for p in os.environ.get("PXR_AR_DEFAULT_SEARCH_PATH", "").split(os.pathsep) if p]
    Ar.DefaultResolver.SetDefaultSearchPath([*own, str(search_folder())])


def named_asset(asset: str) -> Path:
    """The file of a ``NAME/FILE`` asset path, or StageError listing the roots."""
    path = root_file(asset)
    if path is None:
        roots = ", ".join(f"{name}/ ({folder})" for name, folder in asset_roots().items())
        raise StageError(f"{asset}: no such packaged asset (asset roots: {roots})")
    return path
