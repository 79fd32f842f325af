"""Errors and warnings raised while reading a physics stage."""
from __future__ import annotations


class StageError(ValueError):
    """A stage cannot be simulated: missing file, not USD, or a broken physics prim.

    The message is one line naming the file and, where there is one, the prim.
    """


class UnsupportedPrimWarning(UserWarning):
    """A physics prim that graphflow does not simulate; the message names its path and why."""


def warn_unsupported(source: str, path: str, reason: str) -> None:
    """Warn that *path* of stage *source* is not (or only approximately) simulated.

    Issued at the stage file itself (line 0), so Python prints it as one line,
    ``STAGE:0: UnsupportedPrimWarning: PRIM: REASON``, with no source line under it.
    """
    import warnings

    warnings.warn_explicit(UnsupportedPrimWarning(f"{path}: {reason}"), UnsupportedPrimWarning,
                           filename=source, lineno=0)
