"""The ``graphflow`` command: one module per command family, each registering its own parser.

Exit codes (``graphflow.errors``): 0 success; 1 a run that failed (a check, a node, the physics);
2 bad input or usage; 130 interrupted. Every ``GraphflowError`` is printed here, once, one line per
problem, without a traceback unless ``--log-level debug``.
"""
from __future__ import annotations

import argparse
import logging
import signal
import sys
import threading
import warnings

from graphflow import __version__
from graphflow.errors import (
    EXIT_BAD_INPUT,
    EXIT_INTERRUPTED,
    EXIT_OK,
    EXIT_RUN_FAILED,
    GraphflowError,
    interrupted,
)

__all__ = ["build_parser", "main"]


def build_parser() -> argparse.ArgumentParser:
    from graphflow.cli import editing, graphs, report, robot, run, scenarios, stage, studio, sweep, traces

    parser = argparse.ArgumentParser(prog="graphflow", description="Run, check and inspect graphflow action graphs.")
    parser.add_argument("--version", action="version", version=f"graphflow {__version__}")
    commands = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")
    for family in (run, traces, report, scenarios, graphs, editing, stage, robot, sweep, studio):
        family.register(commands)
    return parser


def _one_line_warning(message, category, filename, lineno, line=None) -> str:
    return f"warning: {message}\n"


def _interrupt(_signal_number, _frame):
    raise KeyboardInterrupt


def main(argv: list[str] | None = None) -> int:
    on_main_thread = threading.current_thread() is threading.main_thread()
    # `kill` cleans up like Ctrl-C: no half-written outputs
    previous_handler = signal.signal(signal.SIGTERM, _interrupt) if on_main_thread else None
    previous_format = warnings.formatwarning
    try:
        return _main(argv)
    except KeyboardInterrupt:   # Ctrl-C at any moment: outputs in progress were removed on the way out
        print("graphflow: interrupted", file=sys.stderr)
        return EXIT_INTERRUPTED
    finally:
        warnings.formatwarning = previous_format
        if previous_handler is not None:
            signal.signal(signal.SIGTERM, previous_handler)


def _main(argv: list[str] | None) -> int:
    args = build_parser().parse_args(sweep_shorthand(sys.argv[1:] if argv is None else argv))
    level = getattr(args, "log_level", "warning")
    logging.basicConfig(level=level.upper(), format="%(levelname)s %(name)s: %(message)s", stream=sys.stderr)
    warnings.formatwarning = _one_line_warning
    try:
        return args.handler(args)
    except BrokenPipeError:  # output piped into head & co.: not an error
        sys.stderr.close()
        return EXIT_OK
    except GraphflowError as error:
        if interrupted():   # a Ctrl-C turned into this error on its way (an import, a world build)
            raise KeyboardInterrupt from None
        if isinstance(error.__cause__, BrokenPipeError):   # a print node's reader (head) has gone: done
            sys.stderr.close()
            return EXIT_OK
        if level == "debug":
            raise
        prefix = "graphflow: error: " if error.exit_code == EXIT_BAD_INPUT else "graphflow: run-time error: "
        for line in error.lines():
            print(f"{prefix}{line}", file=sys.stderr)
        return error.exit_code
    except Exception as error:  # a bug: one line, never a traceback unless debugging
        if interrupted():   # numpy's import turns a Ctrl-C into an ImportError
            raise KeyboardInterrupt from None
        if level == "debug":
            raise
        print(f"graphflow: unexpected error: {type(error).__name__}: {error}", file=sys.stderr)
        return EXIT_RUN_FAILED


def sweep_shorthand(argv: list[str]) -> list[str]:
    """``graphflow sweep FILE ...`` is short for ``graphflow sweep run FILE ...``."""
    if len(argv) >= 2 and argv[0] == "sweep" and argv[1] not in ("run", "plot", "-h", "--help"):
        return ["sweep", "run", *argv[1:]]
    return argv
