"""Errors and warnings raised while reading a physics stage."""
from __future__ import annotations


class StageError(ValueError):
    """A stage cannot be simulated: missing file, not USD, or a broken physics prim.

    The message is one line naming the file and, where there is one, the prim.
    """


class UnsupportedPrimWarning(UserWarning):
    """A physics prim that graphflow does not simulate; the message names its path and why."""
