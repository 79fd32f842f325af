"""One error base for everything graphflow refuses or fails, and the exit code each branch means.

``BadInput`` (exit 2) is what the user can fix before anything runs: a file, an option, a stage, a
missing extra. ``RunFailure`` (exit 1) is a run that started and failed: a node, the physics, a
check. The command's last-resort handler catches exactly these two branches; anything else is a bug.
Both also derive from the built-in class callers caught before this base existed (``ValueError``,
``RuntimeError``), so code that catches those keeps working.
"""
from __future__ import annotations

EXIT_OK = 0
EXIT_RUN_FAILED = 1
EXIT_BAD_INPUT = 2
EXIT_INTERRUPTED = 130   # 128 + SIGINT, as shells report a Ctrl-C


class GraphflowError(Exception):
    """Base of every error graphflow raises on purpose; ``exit_code`` is what the command returns for it."""

    exit_code = EXIT_RUN_FAILED

    def lines(self) -> list[str]:
        """The message as the lines the command prints (one problem a line)."""
        return str(self).splitlines() or [type(self).__name__]


class BadInput(GraphflowError, ValueError):
    """Input the user can fix before anything runs (exit 2)."""

    exit_code = EXIT_BAD_INPUT


class RunFailure(GraphflowError, RuntimeError):
    """A run that started and failed (exit 1)."""

    exit_code = EXIT_RUN_FAILED


class MissingExtra(BadInput):
    """A feature whose optional dependencies are not installed; the message says how to install them."""

    def __init__(self, feature: str, extra: str, packages: str):
        self.feature, self.extra = feature, extra
        super().__init__(f"{feature} needs the '{extra}' extra ({packages}): pip install 'graphflow[{extra}]'")


EXTRAS = {
    "viz": "matplotlib and Pillow",
    "ros": "mcap, mcap-ros2-support and rosbags",
    "ray": "Ray",
    "studio": "Starlette, uvicorn and websockets",
}


def require_extra(feature: str, extra: str, *modules: str) -> None:
    """Raise ``MissingExtra`` naming *extra* when one of *modules* cannot be imported."""
    import importlib

    for module in modules:
        try:
            importlib.import_module(module)
        except ImportError:
            raise MissingExtra(feature, extra, EXTRAS[extra]) from None
