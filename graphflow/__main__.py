"""``graphflow`` / ``python -m graphflow``: the command, with Ctrl-C handled from the very first import.

The console script points here rather than at ``graphflow.cli`` so that a Ctrl-C
while the command's modules are still being imported (numpy, networkx,
jsonschema: a good part of a second) exits like one at any later moment: one
line, exit code 130, no traceback.
"""
import sys

EXIT_INTERRUPTED = 130


def main() -> int:
    try:
        from graphflow.cli import main as run_command

        return run_command()
    except KeyboardInterrupt:
        print("graphflow: interrupted", file=sys.stderr)
        return EXIT_INTERRUPTED


if __name__ == "__main__":
    sys.exit(main())
