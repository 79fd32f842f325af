"""``graphflow test PATH...``: every scenario under the paths, a verdict each (``graphflow.verdicts.suite``)."""
from __future__ import annotations

from graphflow.cli import arguments


def register(commands) -> None:
    test = commands.add_parser("test", help="run every graph with checks under the paths; one line each, then 'N passed, M failed'")
    test.add_argument("paths", nargs="+", metavar="PATH", help="graph files or folders (searched recursively)")
    test.add_argument("-j", "--jobs", type=arguments.positive_int, metavar="N", help="processes at once (default: as many as cores)")
    test.add_argument("--junit", metavar="FILE", help="write a JUnit XML report")
    test.add_argument("--traces", metavar="DIR", help="folder for failing scenarios' traces (default: a new temporary folder)")
    test.add_argument("--force", action="store_true", help="overwrite an existing --junit file")
    test.add_argument("--update-golden", action="store_true",
                      help="rewrite the golden trace of every matchesTrace check from this run (the check then holds)")
    test.add_argument("--seeds", type=arguments.positive_int, metavar="N",
                      help="run every scenario as a rate over N seeds (its scenario.randomize drawn per seed)")
    test.add_argument("--min-pass-rate", type=arguments.probability, metavar="P",
                      help="gate of rate scenarios that declare no minPassRate (default 0.8): the Wilson lower bound must reach it")
    test.add_argument("--ray", action="store_true", help="run rate scenarios' episodes on Ray (default: local worker processes)")
    test.set_defaults(handler=command_test)


def command_test(args) -> int:
    from graphflow.verdicts.suite import command_test as run_suite

    return run_suite(args)
