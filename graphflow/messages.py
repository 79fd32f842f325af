"""Error text for users: usd-core's messages without their C++ source locations and internal names.

A node that reads USD (an attribute that is not there, a bad path) fails with usd-core's own
exception text; the executor and the stage loader show it through ``usd_message`` so the line a
user sees names the problem, not ``pxrInternal_...`` frames. No dependencies: the core may use it.
"""
from __future__ import annotations

import re

# usd-core's error text: "Error in 'pxrInternal_v0_26_11__pxrReserved__::UsdStage::Open' at line 1287 in file
# /opt/USD/pxr/usd/usd/stage.cpp : 'the message'" -- only the message is for users
_TF_PREAMBLE = re.compile(r"Error in '[^']*' at line \d+ in file \S+ : ")
_PXR_NAMESPACE = re.compile(r"pxrInternal_\w+?__pxrReserved__::")



def usd_message(error: object) -> str:
    """An error's text on one line; for usd-core's errors the first message, without its C++ source
    location and internal namespace names. Other text is only joined onto one line."""
    text = " ".join(str(error).split())
    if not _TF_PREAMBLE.search(text):
        return _PXR_NAMESPACE.sub("", text)
    text = _PXR_NAMESPACE.sub("", text)
    messages = [part.strip().strip("'").strip() for part in _TF_PREAMBLE.split(text)]
    return next((message for message in messages if message), "unreadable")
