"""``graphflow test PATH...``: every scenario under the paths, a verdict each (``graphflow.verdicts.suite``)."""
from __future__ import annotations

from graphflow.cli import arguments


def register(commands) -> None:
    test = commands.add_parser("test", help="run every graph with checks under the paths; one line each, then 'N passed, M failed'")
    test.add_argument("paths", nargs="+", metavar="PATH", help="graph files or folders (searched recursively)")
    test.add_argument("-j", "--jobs", type=arguments.positive_int, metavar="N", help="processes at once (default: as many as cores)")
    test.add_argument("--junit", metavar="FILE", help="write a JUnit XML report")
    test.add_argument("--traces", metavar="DIR", help="folder for failing scenarios' traces (default: a new temporary folder)")
    test.add_argument("--reports", metavar="DIR", help="write an HTML run report per scenario into DIR (linked from --junit)")
    test.add_argument("--force", action="store_true", help="overwrite an existing --junit file or reports")
    test.set_defaults(handler=command_test)


def command_test(args) -> int:
    from graphflow.verdicts.suite import command_test as run_suite

    return run_suite(args)
