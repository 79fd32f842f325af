"""The one folder a studio serves: every path a request names is resolved inside it, or refused.

Paths come from the browser, so they are untrusted: absolute paths, ``..`` parts and symbolic
links that resolve outside the folder are refused before anything is read or written.
"""
from __future__ import annotations

from pathlib import Path, PurePosixPath

from graphflow.errors import BadInput


class OutsideFolder(BadInput):
    """A requested path that is not inside the served folder."""


class ServedFolder:
    """The folder ``graphflow studio`` was started on (resolved once, symlinks included)."""

    def __init__(self, root):
        self.root = Path(root).resolve()

    def resolve(self, relative: str) -> Path:
        """The file *relative* names under the folder; ``OutsideFolder`` for anything that leaves it."""
        if not isinstance(relative, str) or not relative or "\x00" in relative or "\\" in relative:
            raise OutsideFolder(f"path {relative!r}: give a file path relative to the served folder")
        pure = PurePosixPath(relative)
        if pure.is_absolute() or ".." in pure.parts:
            raise OutsideFolder(f"path {relative!r}: only files under the served folder (no absolute paths, no '..')")
        resolved = (self.root / pure).resolve()
        if resolved != self.root and self.root not in resolved.parents:
            raise OutsideFolder(f"path {relative!r} leads outside the served folder (a symbolic link?)")
        return resolved

    def relative(self, path: Path) -> str:
        return path.resolve().relative_to(self.root).as_posix()

    def graph_files(self, limit: int = 500) -> list[str]:
        """The .json files under the folder (graph candidates), at most *limit*, hidden folders skipped."""
        found = []
        for path in sorted(self.root.rglob("*.json")):
            parts = path.relative_to(self.root).parts
            if any(part.startswith(".") or part == "node_modules" for part in parts):
                continue
            try:
                found.append(self.relative(self.resolve(PurePosixPath(*parts).as_posix())))
            except OutsideFolder:
                continue   # a link out of the folder: not listed, as it cannot be opened
            if len(found) >= limit:
                break
        return found
