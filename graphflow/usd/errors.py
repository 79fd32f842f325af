"""Errors and warnings raised while reading a physics stage."""
from __future__ import annotations


class StageError(ValueError):
    """A stage cannot be simulated: missing file, not USD, or broken physics prims.

    Each problem is one line naming the file and, where there is one, the prim;
    ``problems`` lists them all (a stage with several is reported at once).
    """

    def __init__(self, *problems: str):
        self.problems = list(problems)
        super().__init__("\n".join(self.problems))


class UnsupportedPrimWarning(UserWarning):
    """A physics prim that graphflow does not simulate; the message names its path and why."""
