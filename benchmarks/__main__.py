"""``python -m benchmarks [NAME ...] [--quick]``: run benchmarks, one final line each."""
from __future__ import annotations

import argparse
import importlib
import sys

from . import NAMES, Skip, machine


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m benchmarks", description=__doc__)
    parser.add_argument("names", nargs="*", metavar="NAME",
                        help=f"benchmarks to run (default all): {', '.join(NAMES)}")
    parser.add_argument("--quick", action="store_true", help="tiny configuration: proves it works, figures mean little")
    args = parser.parse_args(argv)
    unknown = [name for name in args.names if name not in NAMES]
    if unknown:
        parser.error(f"unknown benchmark {unknown[0]!r}; choose from {', '.join(NAMES)}")
    print(f"# {machine()}{' (quick)' if args.quick else ''}", flush=True)
    for name in args.names or NAMES:
        module = importlib.import_module(f"{__package__}.{name}")
        try:
            result = module.run(quick=args.quick)
        except Skip as reason:
            result = f"{name}: skipped ({reason})"
        print(result, flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
