"""Errors and warnings raised while reading a physics stage."""
from __future__ import annotations

from graphflow.errors import BadInput


class StageError(BadInput):
    """A stage cannot be simulated: missing file, not USD, or broken physics prims.

    Each problem is one line naming the file and, where there is one, the prim;
    ``problems`` lists them all (a stage with several is reported at once).
    """

    def __init__(self, *problems: str):
        self.problems = list(problems)
        super().__init__("\n".join(self.problems))


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
