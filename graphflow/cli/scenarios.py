"""``graphflow test PATH...``: every scenario under the paths, a verdict each (``graphflow.verdicts.suite``)."""
from __future__ import annotations

from graphflow.cli import arguments
from graphflow.cli.watch import add_watch_option


def register(commands) -> None:
    register_test(commands)
    register_shrink(commands)


def register_test(commands) -> None:
    test = commands.add_parser("test", help="run every graph with checks under the paths; one line each, then 'N passed, M failed'")
    test.add_argument("paths", nargs="+", metavar="PATH", help="graph files or folders (searched recursively)")
    test.add_argument("-j", "--jobs", type=arguments.positive_int, metavar="N", help="processes at once (default: as many as cores)")
    test.add_argument("--junit", metavar="FILE", help="write a JUnit XML report")
    test.add_argument("--traces", metavar="DIR", help="folder for failing scenarios' traces (default: a new temporary folder)")
    test.add_argument("--reports", metavar="DIR", help="write an HTML run report per scenario into DIR (linked from --junit)")
    test.add_argument("--force", action="store_true", help="overwrite an existing --junit file or reports")
    test.add_argument("--update-golden", action="store_true",
                      help="rewrite the golden trace of every matchesTrace check from this run (the check then holds)")
    test.add_argument("--seeds", type=arguments.positive_int, metavar="N",
                      help="run every scenario as a rate over N seeds (its scenario.randomize drawn per seed)")
    test.add_argument("--min-pass-rate", type=arguments.probability, metavar="P",
                      help="gate of rate scenarios that declare no minPassRate (default 0.8): the Wilson lower bound must reach it")
    test.add_argument("--ray", action="store_true", help="run rate scenarios' episodes on Ray (default: local worker processes)")
    add_watch_option(test, "a scenario, table, stage or scripted-input file under the paths")
    test.set_defaults(handler=command_test)


def register_shrink(commands) -> None:
    shrink = commands.add_parser("shrink", help="shrink a failing seed of a rate scenario to the smallest perturbation "
                                                "that fails the same way; print it as --set arguments and a table row")
    shrink.add_argument("scenario", help="graph file with scenario.randomize")
    shrink.add_argument("--seed", type=int, required=True, help="the failing seed (graphflow test lists them)")
    shrink.set_defaults(handler=command_shrink)


def command_shrink(args) -> int:
    """Exit 0 with the shrunk case printed; 2 when the seed passes or the scenario draws nothing."""
    import json
    import logging

    from graphflow.errors import EXIT_OK
    from graphflow.verdicts.shrink import shrink

    logging.getLogger("graphflow").setLevel(logging.ERROR)   # each trial's warnings would bury the result
    shrunk = shrink(args.scenario, args.seed)
    print(f"smallest failing case ({len(shrunk.kept)} of {len(shrunk.drawn)} parameters, {shrunk.runs} runs):")
    print(f"  {shrunk.command()}")
    for note in shrunk.notes():
        print(f"  note: {note}")
    print("as a table row (graphflow-cases):")
    print(f"  {json.dumps(shrunk.table_row())}")
    return EXIT_OK


def command_test(args) -> int:
    from graphflow.sweep.scenario_rates import run_rate
    from graphflow.verdicts.suite import command_test as run_suite

    if not args.watch:
        return run_suite(args, rate_runner=run_rate)
    from graphflow.cli.watch import watch
    from graphflow.errors import EXIT_BAD_INPUT
    from graphflow.watching import Watcher, paths_files

    def after_run(code: int) -> None:
        if code != EXIT_BAD_INPUT:   # the suite wrote its --junit and --reports: the next run replaces them
            args.force = True

    return watch(lambda: run_suite(args, rate_runner=run_rate), Watcher(lambda: paths_files(args.paths)),
                 title=f"graphflow test {' '.join(args.paths)}", after_run=after_run)
