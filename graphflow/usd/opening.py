"""Opening a stage the one way graphflow does: asset roots, URL remaps, and one line per missing layer.

``open_composed(path)`` installs the asset roots on USD's resolver (``graphflow/ur10.usda``), opens
the stage through the remap table (``graphflow.usd.remap``) and turns every reference, payload or
sublayer USD could not open into one line naming the layer, the asset and the prims that lost
their contents. USD's own C++ warnings about them (printed twice, on stderr) never reach the user.
Missing layers are ``MissingLayerWarning`` lines and the stage opens without them (import, run: a node
touching a lost prim fails naming itself), except where the user asks whether a stage is complete:
``graphflow validate`` and ``graphflow stage`` refuse them (``StageError``, exit 2) unless given
``--allow-missing-assets`` or ``GRAPHFLOW_ALLOW_MISSING_ASSETS=1``.
"""
from __future__ import annotations

import contextlib
import os
import re
import sys
import warnings
from contextvars import ContextVar
from pathlib import Path

from graphflow.usd.errors import StageError

ALLOW_VARIABLE = "GRAPHFLOW_ALLOW_MISSING_ASSETS"
_refused: ContextVar[bool] = ContextVar("graphflow_missing_layers_refused", default=False)
_ARC = re.compile(r"Could not open asset @(?P<asset>[^@]*)@ for (?P<arc>reference|payload) introduced by "
                  r"@(?P<layer>[^@]*)@<(?P<prim>[^>]*)>")
_SUBLAYER = re.compile(r"Could not load sublayer @(?P<asset>[^@]*)@ of layer @(?P<layer>[^@]*)@")


class MissingLayerWarning(UserWarning):
    """A layer of a stage could not be opened and the stage was allowed to open without it (one line)."""


@contextlib.contextmanager
def missing_layers_refused(refused: bool = True):
    """Within this block (validate, stage), a stage with a layer that cannot be opened is a StageError."""
    token = _refused.set(refused)
    try:
        yield
    finally:
        _refused.reset(token)


def open_composed(path: str | os.PathLike):
    """The ``Usd.Stage`` at *path*, composed with graphflow's asset roots and remaps; see the module docstring."""
    from pxr import Usd

    from graphflow.usd.asset_roots import install_search_path
    from graphflow.usd.downloads import download_cache
    from graphflow.usd.remap import RemappedLayers, project_folder_setting, remap_table

    install_search_path()
    label = str(path)
    table = remap_table(Path(path).parent)
    cache = download_cache(Path(path).parent, project_folder_setting)
    layers = RemappedLayers(table, cache)
    with native_stderr_captured():
        root = layers.root(str(path)) if table or cache is not None else None
        stage = Usd.Stage.Open(root) if root is not None else Usd.Stage.Open(str(path))
        errors = [str(error) for error in stage.GetCompositionErrors()] if stage is not None else []
    lines = missing_layer_lines(label, errors, table, cache.failures if cache is not None else {})
    if lines and _refused.get() and os.environ.get(ALLOW_VARIABLE, "") in ("", "0"):
        raise StageError(*lines)
    for line in lines:
        warnings.warn(MissingLayerWarning(line), stacklevel=2)
    return stage


def missing_layer_lines(label: str, messages: list[str], table, failures: dict | None = None) -> list[str]:
    """One line per asset that cannot be opened: the layer naming it, the asset, and the prims left without it."""
    from pxr import Sdf

    lost: dict[tuple[str, str, str], list[str]] = {}
    lines = []
    for message in (" ".join(m.split()) for m in messages):
        match = _ARC.search(message) or _SUBLAYER.search(message)
        if match is None:
            lines.append(f"{label}: {message}")
            continue
        asset = re.sub(r"^(https?|omniverse):/(?!/)", r"\1://", match["asset"])   # USD prints https:/host
        layer = Path(label).name if match["layer"].startswith("anon:") else Path(match["layer"]).name
        arc = match["arc"] if "arc" in match.groupdict() else "sublayer"
        prims = lost.setdefault((asset, arc, layer), [])
        if arc != "sublayer":
            prims.append(str(Sdf.Path(match["prim"]).StripAllVariantSelections()))
    # usd-core composes in parallel: its messages come in any order, so the lines are put in one
    lines.sort()
    for (asset, arc, layer), prims in sorted(lost.items()):
        if arc == "sublayer":
            what = f"a sublayer of layer {layer}: prims lost: every prim that layer defines"
        else:
            shown = ", ".join(sorted(set(prims)))
            what = (f"the {arc} of {shown} in layer {layer}: prims lost: everything that {arc} puts "
                    f"below {shown}")
        lines.append(f"{label}: cannot open {asset}, {what}{_hint(asset, table, failures or {})}")
    return lines


def _hint(asset: str, table, failures: dict) -> str:
    if asset in failures:
        return f" (download failed: {failures[asset]})"
    if "://" in asset and table.apply(asset) is None:
        return " (map its URL prefix to a local folder in graphflow.toml [assets.remap] or GRAPHFLOW_ASSET_REMAP)"
    if any(asset.startswith(folder) for _, folder in table.entries):
        return " (remapped by graphflow.toml or GRAPHFLOW_ASSET_REMAP: the file is not in that folder)"
    return ""


@contextlib.contextmanager
def native_stderr_captured():
    """Keep what USD's C++ prints on stderr (its TfWarnings) off the terminal while a stage opens."""
    import ctypes
    import tempfile

    libc = ctypes.CDLL(None)
    sys.stderr.flush()
    libc.fflush(None)
    saved = os.dup(2)
    with tempfile.TemporaryFile() as sink:
        os.dup2(sink.fileno(), 2)
        try:
            yield
        finally:
            libc.fflush(None)
            os.dup2(saved, 2)
            os.close(saved)
