"""Errors and warnings raised while reading a physics stage."""
from __future__ import annotations

import re

# usd-core's error text: "Error in 'pxrInternal_v0_26_11__pxrReserved__::UsdStage::Open' at line 1287 in file
# /opt/USD/pxr/usd/usd/stage.cpp : 'the message'" -- only the message is for users
_TF_PREAMBLE = re.compile(r"Error in '[^']*' at line \d+ in file \S+ : ")
_PXR_NAMESPACE = re.compile(r"pxrInternal_\w+?__pxrReserved__::")


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


def usd_message(error) -> str:
    """An error's text on one line; for usd-core's errors the first message, without its C++ source
    location and internal namespace names. Other text is only joined onto one line."""
    text = " ".join(str(error).split())
    if not _TF_PREAMBLE.search(text):
        return _PXR_NAMESPACE.sub("", text)
    text = _PXR_NAMESPACE.sub("", text)
    messages = [part.strip().strip("'").strip() for part in _TF_PREAMBLE.split(text)]
    return next((message for message in messages if message), "unreadable")
