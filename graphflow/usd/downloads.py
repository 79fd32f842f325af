"""A download cache for ``http(s)`` assets: a stage's URL opened from a local copy fetched once.

Off unless a folder is given: ``GRAPHFLOW_ASSET_CACHE=FOLDER`` or, in the nearest graphflow.toml,
``cache = "FOLDER"`` under ``[assets]``. An ``http(s)`` asset no remap covers is fetched to
``FOLDER/HOST/PATH`` (atomically; a file already there is used as is), as are the relative assets of
the layers fetched that way, so the copy keeps the URL's layout. What cannot be fetched stays a
missing layer, its line saying why.
"""
from __future__ import annotations

import os
import tempfile
import urllib.error
import urllib.request
from pathlib import Path
from urllib.parse import urljoin, urlsplit

ENVIRONMENT_VARIABLE = "GRAPHFLOW_ASSET_CACHE"
TIMEOUT = 30.0   # s per request


class DownloadCache:
    """Fetches URLs into a folder, remembering where each cached file came from and what failed."""

    def __init__(self, folder: Path):
        self.folder = folder
        self.failures: dict[str, str] = {}    # URL -> why it could not be fetched
        self._origins: dict[str, str] = {}    # cached file (resolved) -> its URL

    def fetch(self, url: str) -> str | None:
        """The cached file of *url* (fetched now if it is not there yet), or None when it cannot be fetched."""
        parts = urlsplit(url)
        target = self.folder / parts.netloc.replace(":", "_") / parts.path.lstrip("/")
        if not target.is_file():
            try:
                self._download(url, target)
            except (OSError, ValueError) as error:   # urllib's errors are OSErrors; a bad URL a ValueError
                self.failures[url] = " ".join(str(getattr(error, "reason", error)).split())
                return None
        self._origins[str(target.resolve())] = url
        return str(target)

    def origin(self, path: str) -> str | None:
        """The URL a cached file came from (None for the user's own files)."""
        return self._origins.get(str(Path(path).resolve()))

    def relative(self, layer_path: str, asset: str) -> str | None:
        """A relative asset of a fetched layer, fetched beside it; None when the layer is not a fetched one."""
        origin = self.origin(layer_path)
        return self.fetch(urljoin(origin, asset)) if origin is not None else None

    @staticmethod
    def _download(url: str, target: Path) -> None:
        target.parent.mkdir(parents=True, exist_ok=True)
        with urllib.request.urlopen(url, timeout=TIMEOUT) as response:
            data = response.read()
        handle, temporary = tempfile.mkstemp(dir=target.parent, prefix=f".{target.name}.")
        with os.fdopen(handle, "wb") as stream:
            stream.write(data)
        os.replace(temporary, target)


def download_cache(start: Path, setting) -> DownloadCache | None:
    """The cache in force: the environment variable's folder, else graphflow.toml's ``[assets] cache``
    (*setting* returns it with the file's folder, or None)."""
    folder = os.environ.get(ENVIRONMENT_VARIABLE, "")
    if folder:
        return DownloadCache(Path(folder).expanduser().resolve())
    found = setting(start, "cache")
    return DownloadCache(found) if found is not None else None
