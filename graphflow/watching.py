"""Watching the files a graph run reads, to run it again when one changes (``run --watch``, ``test --watch``, the studio).

The files: the graph, its stage and every local layer the stage composes (sublayers, references,
payloads, followed recursively), the scenario's keys, gamepad and topics files, and for a scenario
table its graph and the cases' input files. A file's state is its (size, mtime) from ``os.stat``,
polled: a handful of files every half second costs nothing, works on every filesystem (network and
container mounts where inotify sees nothing) and needs no dependency; the set of files is read
again after each change, so a sublayer added to the stage is watched from then on.
"""
from __future__ import annotations

import json
import os
import time
from pathlib import Path
from typing import Callable, Iterable

POLL_SECONDS = 0.5
WATCHED_IN_FOLDERS = (".json", ".usda", ".usd", ".usdc", ".usdz")   # what a folder given to `test` is watched for
_INPUT_FILES = ("keys", "gamepad", "mouse", "topics")   # scenario (and table case) entries that may name a file


def graph_files(path: str | os.PathLike) -> list[Path]:
    """The local files a run of the graph (or scenario table) at *path* reads, itself first.

    Read leniently: a file that is not JSON yet (an edit in progress) is watched alone, and a stage
    or layer that cannot be opened is watched without what it would compose.
    """
    path = Path(path)
    files = [path]
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return files
    if not isinstance(data, dict):
        return files
    settings, scenario = data.get("settings"), data.get("scenario")
    if isinstance(settings, dict) and isinstance(settings.get("stage"), str):
        files.extend(stage_files(settings["stage"], path.parent))
    for section in [scenario, *(data.get("cases") or [])]:
        if isinstance(section, dict):
            files.extend(path.parent / section[key] for key in _INPUT_FILES if isinstance(section.get(key), str))
    if isinstance(data.get("graph"), str) and data.get("format") == "graphflow-cases":
        files.extend(graph_files(path.parent / data["graph"]))
    return list(dict.fromkeys(files))


def stage_files(reference: str, base_dir: Path) -> list[Path]:
    """The stage file a graph names and every local layer it composes, recursively (URLs and packaged assets skipped)."""
    from graphflow.errors import BadInput
    from graphflow.usd.resolver import ASSET_PREFIX, resolve_stage

    if reference.startswith(ASSET_PREFIX):
        return []   # part of the installed package: it changes when graphflow does
    try:
        stage = resolve_stage(reference, base_dir).resolve()
    except BadInput:
        return []
    found: list[Path] = []
    pending = [stage]
    while pending:
        layer = pending.pop()
        if layer in found:
            continue
        found.append(layer)
        pending.extend(_composed_layers(layer))
    return found


def _composed_layers(layer: Path) -> list[Path]:
    if not layer.is_file():
        return []
    from pxr import Sdf

    try:
        opened = Sdf.Layer.OpenAsAnonymous(str(layer))   # anonymous: never USD's cached copy of an edited file
    except Exception:   # pxr raises Tf.ErrorException for a layer it cannot parse: watched, composing nothing
        return []
    if opened is None:
        return []
    assets = [asset for asset in opened.GetCompositionAssetDependencies() if asset and "://" not in asset]
    return [(layer.parent / asset).resolve() if not Path(asset).is_absolute() else Path(asset) for asset in assets]


def folder_files(folder: Path) -> list[Path]:
    """The graph, table and stage files under a folder given to ``graphflow test`` (a new one is a change too)."""
    return sorted(path for path in folder.rglob("*") if path.suffix in WATCHED_IN_FOLDERS and path.is_file())


def paths_files(paths: Iterable[str | os.PathLike]) -> list[Path]:
    """Every file ``graphflow test PATHS`` reads: the files named and found under folders, with what each graph reads."""
    files: list[Path] = []
    for given in map(Path, paths):
        if given.is_dir():
            files.append(given)   # its state is the files in it: a scenario added is a change
        for found in (folder_files(given) if given.is_dir() else [given]):
            files.extend(graph_files(found) if found.suffix == ".json" else [found])
    return list(dict.fromkeys(files))


def fingerprint(files: Iterable[Path]) -> dict[str, tuple | None]:
    """Each file's (size, mtime in ns), a folder's watched files by name, None for a file that is not there."""
    state: dict[str, tuple | None] = {}
    for path in files:
        if path.is_dir():
            state[str(path)] = tuple(str(found.relative_to(path)) for found in folder_files(path))
            continue
        try:
            found = os.stat(path)
        except OSError:
            state[str(path)] = None
            continue
        state[str(path)] = (found.st_size, found.st_mtime_ns)
    return state


class WatchedFiles:
    """The files *files_of()* names and their state; the set is read again only when the state changed (cheap to poll)."""

    def __init__(self, files_of: Callable[[], list[Path]]):
        self.files_of = files_of
        self.files = files_of()
        self.last = fingerprint(self.files)

    def state(self) -> dict[str, tuple | None]:
        """The files' state now; after a change the set is read again (a sublayer added is watched from then on)."""
        now = fingerprint(self.files)
        if now != self.last:
            self.files = self.files_of()
            now = fingerprint(self.files)
        self.last = now
        return now


class Watcher:
    """Waits for a change to the files *files_of()* names; *sleep* is injectable so tests drive it without waiting.

    ``wait()`` polls every *interval* seconds and returns the files that changed once two polls in a
    row agree (a save in progress is not taken for the edit).
    """

    def __init__(self, files_of: Callable[[], list[Path]], *, interval: float = POLL_SECONDS,
                 sleep: Callable[[float], None] | None = None):
        self.watched = WatchedFiles(files_of)
        self.interval, self.sleep = interval, sleep or time.sleep

    @property
    def files(self) -> list[Path]:
        return self.watched.files

    def wait(self) -> list[str]:
        """Block until a watched file changes, appears or goes; the paths that changed."""
        before = self.watched.last
        while True:
            self.sleep(self.interval)
            now = fingerprint(self.watched.files)
            if now == before:
                continue
            while True:   # settle: the same state twice in a row
                self.sleep(self.interval)
                again = fingerprint(self.watched.files)
                if again == now:
                    break
                now = again
            changed = _changes(before, now)
            self.watched.state()   # the set read again, its state taken as the new starting point
            return changed


def _changes(before: dict, now: dict) -> list[str]:
    """The files that changed, appeared or went between two states (a folder's by the files added to or gone from it)."""
    changed: list[str] = []
    for path, state in now.items():
        old = before.get(path)
        if state == old:
            continue
        if Path(path).is_dir() and isinstance(old, tuple):
            changed.extend(str(Path(path) / name) for name in sorted(set(state or ()) ^ set(old)))
        else:
            changed.append(path)
    return changed
