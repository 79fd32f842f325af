"""Keep PyBullet's native banner lines ('pybullet build time ...', 'argv[0]=') out of the output.

The C library prints them with printf when the module is imported and when a
client connects; stdout belongs to the graph's own log lines (and to pipes
such as ``graphflow run ... | grep``) and stderr to one-line errors, so the
banners are sent to /dev/null instead.
"""
from __future__ import annotations

import ctypes
import os
import sys
from contextlib import contextmanager

_libc = ctypes.CDLL(None)


@contextmanager
def native_output_silenced(*descriptors: int):
    """Point the given file descriptors at /dev/null while native code runs, flushing C buffers on both sides."""
    sys.stdout.flush()
    sys.stderr.flush()
    _libc.fflush(None)
    saved = [os.dup(fd) for fd in descriptors]
    devnull = os.open(os.devnull, os.O_WRONLY)
    try:
        for fd in descriptors:
            os.dup2(devnull, fd)
        yield
    finally:
        _libc.fflush(None)
        for fd, original in zip(descriptors, saved):
            os.dup2(original, fd)
            os.close(original)
        os.close(devnull)


def native_stdout_silenced():
    """Silence only stdout (a client connecting prints 'argv[0]=' there)."""
    return native_output_silenced(1)


def route_native_stdout_to_stderr() -> None:
    """For a whole GUI run: native code's stdout goes to stderr, Python's stdout keeps the real one.

    The PyBullet window's threads print OpenGL and thread diagnostics at any time, not only while
    connecting, so a scoped redirection cannot catch them. Only the CLI, which owns the process,
    calls this.
    """
    sys.stdout.flush()
    _libc.fflush(None)
    real_stdout = os.dup(1)
    os.dup2(2, 1)
    sys.stdout = os.fdopen(real_stdout, "w", buffering=1, encoding=sys.stdout.encoding, errors=sys.stdout.errors)
