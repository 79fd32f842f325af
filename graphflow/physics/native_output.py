"""Keep PyBullet's native banner lines ('pybullet build time ...', 'argv[0]=') off stdout.

The C library prints them with printf when the module is imported and when a
client connects; stdout belongs to the graph's own log lines (and to pipes
such as ``graphflow run ... | grep``), so they are sent to /dev/null instead.
"""
from __future__ import annotations

import ctypes
import os
import sys
from contextlib import contextmanager

_libc = ctypes.CDLL(None)


@contextmanager
def native_stdout_silenced():
    """Point file descriptor 1 at /dev/null while native code runs, flushing C buffers on both sides."""
    sys.stdout.flush()
    _libc.fflush(None)
    saved = os.dup(1)
    devnull = os.open(os.devnull, os.O_WRONLY)
    try:
        os.dup2(devnull, 1)
        yield
    finally:
        _libc.fflush(None)
        os.dup2(saved, 1)
        os.close(saved)
        os.close(devnull)
