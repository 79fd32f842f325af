"""``--watch`` for ``graphflow run`` and ``graphflow test``: run, then run again each time a file the run reads changes.

Each run starts after a separator line naming what changed and ends with a verdict line; bad input
(a graph saved half-edited, a misspelled prim) prints its one-line error and the watch goes on, as does
a failing run. Ctrl-C ends it: ``graphflow.cli.main`` exits 130. The files watched and how are
``graphflow.watching``'s, the same the studio uses.
"""
from __future__ import annotations

import os
import sys
from typing import Callable

from graphflow.errors import EXIT_BAD_INPUT, EXIT_OK, EXIT_RUN_FAILED, GraphflowError, interrupted
from graphflow.watching import Watcher

VERDICTS = {EXIT_OK: "passed", EXIT_RUN_FAILED: "failed", EXIT_BAD_INPUT: "bad input"}


def add_watch_option(parser, what: str) -> None:
    parser.add_argument("--watch", action="store_true",
                        help=f"run again each time {what} changes on disk (polled twice a second); Ctrl-C stops")


def run_guarded(run_once: Callable[[], int], say: Callable[[str], None]) -> int:
    """One run's exit code; its bad input or failure printed as ``graphflow`` prints it, never raised."""
    try:
        return run_once()
    except GraphflowError as error:
        if interrupted():
            raise KeyboardInterrupt from None
        prefix = "graphflow: error: " if error.exit_code == EXIT_BAD_INPUT else "graphflow: run-time error: "
        for line in error.lines():
            say(f"{prefix}{line}")
        return error.exit_code
    except Exception as error:   # a bug in one run: said in one line, the watch goes on
        if interrupted():
            raise KeyboardInterrupt from None
        say(f"graphflow: unexpected error: {type(error).__name__}: {error}")
        return EXIT_RUN_FAILED


def watch(run_once: Callable[[], int], watcher: Watcher, *, title: str, after_run: Callable[[int], None] = lambda code: None,
          say: Callable[[str], None] | None = None, runs: int | None = None) -> int:
    """Run, then wait for a change and run again, until Ctrl-C (``KeyboardInterrupt`` to the caller).

    *after_run* hears each exit code (``run`` lets later runs replace the outputs the earlier wrote);
    *runs* stops after that many runs, returning the last exit code (tests; None: until interrupted).
    """
    say = say or (lambda text: print(text, file=sys.stderr, flush=True))
    count, code = 0, EXIT_OK
    changed: list[str] = []
    while runs is None or count < runs:
        count += 1
        cause = "first run" if not changed else f"changed: {', '.join(map(_shown, changed))}"
        say(f"======== {title}: run {count} ({cause}) ========")
        code = run_guarded(run_once, say)
        after_run(code)
        say(f"======== {title}: run {count} {VERDICTS.get(code, f'exit {code}')} (exit {code}); "
            f"watching {len(watcher.files)} file{'s' if len(watcher.files) != 1 else ''}, Ctrl-C stops ========")
        if runs is not None and count >= runs:
            break
        changed = watcher.wait()
    return code


def _shown(path: str) -> str:
    relative = os.path.relpath(path)
    return path if relative.startswith("..") else relative
