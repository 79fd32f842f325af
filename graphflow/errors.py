"""One error base for everything graphflow refuses or fails, and the exit code each branch means.

``BadInput`` (exit 2) is what the user can fix before anything runs: a file, an option, a stage, a
missing extra. ``RunFailure`` (exit 1) is a run that started and failed: a node, the physics, a
check. The command's last-resort handler catches exactly these two branches; anything else is a bug.
Both also derive from the built-in class callers caught before this base existed (``ValueError``,
``RuntimeError``), so code that catches those keeps working.
"""
from __future__ import annotations

from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:   # imported for the annotations only: this module loads first, before the Ctrl-C handler is in place
    from collections.abc import Callable, Sequence
    from importlib.abc import Loader
    from importlib.machinery import ModuleSpec
    from types import ModuleType

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


# ---------------------------------------------------------------- Ctrl-C in the command

class _Interrupts:
    """The command's Ctrl-C state: ``pending`` once one came; ``deferred`` while it is only noted."""

    pending = False
    deferred = False


def is_the_command() -> bool:
    """True when this process is ``python -m graphflow`` or the ``graphflow`` console script."""
    import sys

    arguments = list(getattr(sys, "orig_argv", ()))
    as_module = any(arguments[i:i + 2] == ["-m", "graphflow"] for i in range(len(arguments)))
    script = sys.argv[0] if sys.argv else ""
    return as_module or script.replace("\\", "/").rsplit("/", 1)[-1] in ("graphflow", "graphflow.exe")


def defer_interrupts() -> None:
    """At the command's first instruction: a Ctrl-C is noted, not raised, until ``raise_interrupts``.

    Until the command's own handler is running (the package import, ``runpy``, the ``__main__``
    import) nothing of graphflow could catch a ``KeyboardInterrupt``; so it waits there. A library
    user's process is left alone: its Ctrl-C stays Python's.
    """
    import signal
    import threading

    if threading.current_thread() is not threading.main_thread() or not is_the_command():
        return
    if signal.getsignal(signal.SIGINT) is signal.default_int_handler:
        _Interrupts.deferred = True
        signal.signal(signal.SIGINT, _on_interrupt)


def note_interrupt() -> None:
    """A Ctrl-C that arrived before the handler was in place (the command reports it at once)."""
    _Interrupts.pending = True


def raise_interrupts() -> None:
    """From here a Ctrl-C raises ``KeyboardInterrupt`` (and one noted before is raised now)."""
    _Interrupts.deferred = False
    if _Interrupts.pending:
        raise KeyboardInterrupt


def interrupted() -> bool:
    """A Ctrl-C came, even if the code it interrupted swallowed the ``KeyboardInterrupt`` (a C++ plugin
    load, numpy turning it into an ``ImportError``, a ``__del__``): the command then still stops."""
    return _Interrupts.pending


def interrupt_handled() -> None:
    """The code that caught the ``KeyboardInterrupt`` finishes on purpose (a sweep keeps its episodes)."""
    _Interrupts.pending = False


def raise_if_interrupted() -> None:
    if _Interrupts.pending:
        raise KeyboardInterrupt


def _on_interrupt(_signal_number: int, _frame: object) -> None:
    _Interrupts.pending = True
    if not _Interrupts.deferred:
        raise KeyboardInterrupt


_LOADED_WITH_INTERRUPTS_NOTED = ("pxr", "pybullet", "networkx")


class _DeferWhileLoading:
    """Import hook of the command: while a ``pxr``, ``pybullet`` or ``networkx`` module loads, a Ctrl-C is only noted.

    usd-core loads its library modules from C++ (``TfScriptModuleLoader``), which prints a Python
    error with its traceback and carries on: a ``KeyboardInterrupt`` raised there would be a
    traceback on stderr and then lost. PyBullet's C initialisation imports modules of its own: a
    ``KeyboardInterrupt`` raised inside those nested imports leaves an import lock held and the
    process hangs. networkx's submodules import their partly loaded package, which takes and drops its
    module lock: a ``KeyboardInterrupt`` raised inside that step left the lock held and the command hung
    releasing it (found by tests/cli/test_interrupts.py at one event count). Noted instead, it is raised
    as soon as the import is done.
    """

    def find_spec(self, name: str, path: Sequence[str] | None = None, target: object = None) -> ModuleSpec | None:
        if name.split(".", 1)[0] not in _LOADED_WITH_INTERRUPTS_NOTED:
            return None
        from importlib.machinery import PathFinder

        spec = PathFinder.find_spec(name, path)
        if spec is not None and spec.loader is not None and hasattr(spec.loader, "exec_module"):
            spec.loader = _DeferredLoader(spec.loader)  # type: ignore[assignment]  # a Loader by duck typing
        return spec


class _DeferredLoader:
    """A module's own loader, run with a Ctrl-C only noted (``_DeferWhileLoading``): both steps, since an
    extension module runs its C initialisation in ``create_module``."""

    def __init__(self, loader: Loader):
        self.loader = loader

    def create_module(self, spec: ModuleSpec) -> ModuleType | None:
        module: ModuleType | None = self._noting_interrupts(self.loader.create_module, spec)
        return module

    def exec_module(self, module: ModuleType) -> None:
        self._noting_interrupts(self.loader.exec_module, module)

    @staticmethod
    def _noting_interrupts(step: Callable[[Any], Any], argument: Any) -> Any:
        outermost = not _Interrupts.deferred
        _Interrupts.deferred = True
        try:
            result = step(argument)
        finally:
            if outermost:
                _Interrupts.deferred = False
        if outermost:
            raise_if_interrupted()
        return result

    def __getattr__(self, name: str) -> object:
        return getattr(self.loader, name)


def defer_interrupts_while_loading_usd() -> None:
    """Install ``_DeferWhileLoading`` (the command only: a library keeps Python's own import system)."""
    import sys

    if not any(isinstance(finder, _DeferWhileLoading) for finder in sys.meta_path):
        sys.meta_path.insert(0, _DeferWhileLoading())
