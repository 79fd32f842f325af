"""``graphflow`` / ``python -m graphflow``: the command, with Ctrl-C handled from the very first instruction.

The package's first lines (``graphflow/__init__.py``) note a Ctrl-C instead of raising it while
nothing could catch it yet; ``main`` raises a noted one inside its handler and from then on a Ctrl-C
is a ``KeyboardInterrupt`` again. One that the interrupted code swallowed (usd-core's C++ plugin
loading, numpy's import turning it into an ``ImportError``, a ``__del__`` during the world build) is
still noted, so the command stops at the next safe point. Every way ends in one line and exit 130.
"""
import sys

EXIT_INTERRUPTED = 130


def _quiet_interrupts(unraisable) -> None:
    """An interrupt inside a ``__del__`` or a callback is noted by the handler; not a traceback."""
    if not isinstance(unraisable.exc_value, KeyboardInterrupt):
        sys.__unraisablehook__(unraisable)


def main() -> int:
    try:
        from graphflow.errors import defer_interrupts_while_loading_usd, interrupted, raise_interrupts

        sys.unraisablehook = _quiet_interrupts
        defer_interrupts_while_loading_usd()
        raise_interrupts()
        from graphflow.cli import main as run_command

        code = run_command()
        if code != EXIT_INTERRUPTED and interrupted():   # swallowed somewhere; the command already said so otherwise
            raise KeyboardInterrupt
        return code
    except KeyboardInterrupt:
        print("graphflow: interrupted", file=sys.stderr)
        return EXIT_INTERRUPTED
    except BaseException:
        if "graphflow.errors" in sys.modules and sys.modules["graphflow.errors"].interrupted():
            print("graphflow: interrupted", file=sys.stderr)
            return EXIT_INTERRUPTED
        raise


if __name__ == "__main__":
    sys.exit(main())
