"""``graphflow sweep run SWEEP`` (short: ``graphflow sweep SWEEP``) and ``graphflow sweep plot DIR``."""
from __future__ import annotations

from graphflow.cli import arguments


def register(commands) -> None:
    sweep = commands.add_parser("sweep", help="many episodes of one graph: a grid / random samples of overrides x "
                                              "seeds (docs/sweeps.md); 'graphflow sweep plot DIR' plots the results")
    actions = sweep.add_subparsers(dest="sweep_command", required=True, metavar="SWEEP_COMMAND")
    run = actions.add_parser("run", help="run a sweep file's episodes (graphflow sweep FILE is short for this)")
    run.add_argument("sweep", metavar="SWEEP_FILE", help="sweep JSON file")
    run.add_argument("--out", metavar="DIR", help="results folder (default sweep-results/SWEEP_NAME)")
    run.add_argument("-j", "--jobs", type=arguments.positive_int, metavar="N", help="worker processes (default: one per core)")
    run.add_argument("--ray", nargs="?", const="", metavar="ADDRESS",
                     help="run the episodes on Ray: no ADDRESS or 'local' starts a local Ray, 'auto' joins the "
                          "running cluster (needs pip install 'graphflow[ray]')")
    run.add_argument("--resume", action="store_true", help="run only the episodes the results folder lacks")
    run.add_argument("--force", action="store_true", help="discard the results folder's episodes and start over")
    run.set_defaults(handler=command_sweep_run)

    plot = actions.add_parser("plot", help="success map over two parameters, or rate against one")
    plot.add_argument("results", metavar="DIR", help="the results folder (--out of the sweep)")
    plot.add_argument("-o", "--output", required=True, metavar="FILE", help="picture file (.png, .svg, .pdf)")
    plot.add_argument("--kind", choices=["map", "curve"],
                      help="success map over two parameters or rate against one (default: map if 2+ parameters)")
    plot.add_argument("--x", metavar="PARAMETER", help="parameter on the x axis (default the first)")
    plot.add_argument("--y", metavar="PARAMETER", help="parameter on the y axis / per curve (default the second)")
    plot.add_argument("--metric", metavar="NAME", help="with --kind map: colour by this metric's median instead of "
                                                       "the success rate")
    plot.add_argument("--force", action="store_true", help="overwrite an existing picture")
    plot.set_defaults(handler=command_sweep_plot)


def command_sweep_run(args) -> int:
    from graphflow.sweep.session import run_sweep

    return run_sweep(args.sweep, out=args.out, jobs=args.jobs, use_ray=args.ray is not None,
                     ray_address=None if args.ray in (None, "") else args.ray, resume=args.resume, force=args.force)


def command_sweep_plot(args) -> int:
    from graphflow.sweep.plot import plot_command

    return plot_command(args)
