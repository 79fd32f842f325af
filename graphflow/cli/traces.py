"""Commands about what a run left behind and how a graph looks: ``trace diff``, ``plot``, ``draw``."""
from __future__ import annotations

from graphflow.document import load_document
from graphflow.errors import EXIT_OK, BadInput, require_extra
from graphflow.files import atomic_output

EXIT_TRACES_DIFFER = 1   # graphflow trace diff, like diff(1)


def register(commands) -> None:
    trace = commands.add_parser("trace", help="work with run traces (graphflow run --trace)")
    trace_commands = trace.add_subparsers(dest="trace_command", required=True, metavar="TRACE_COMMAND")
    trace_diff = trace_commands.add_parser(
        "diff", help="print the first tick and field where two traces differ (exit 0 identical, 1 different)")
    trace_diff.add_argument("left", metavar="A", help="trace file")
    trace_diff.add_argument("right", metavar="B", help="trace file")
    trace_diff.add_argument("--tolerance", nargs="?", const="", metavar="VALUE|FILE",
                            help="compare floats within tolerances (alone: the defaults of docs/trace.md; a number: "
                                 "that absolute bound for every float; a JSON file: per kind and per field); "
                                 "exec pulses, phases, statuses and logs stay exact")
    trace_diff.set_defaults(handler=command_trace_diff)

    draw = commands.add_parser("draw", help="draw a graph: nodes, exec and data edges, left to right in execution order")
    draw.add_argument("graph", help="graph JSON file")
    draw.add_argument("-o", "--output", required=True, metavar="FILE", help="picture file (.svg, .png, .mmd, .dot)")
    draw.add_argument("--format", choices=["svg", "png", "mermaid", "dot"], help="picture format (default: from the suffix)")
    draw.add_argument("--force", action="store_true", help="overwrite an existing picture")
    draw.set_defaults(handler=command_draw)

    plot = commands.add_parser("plot", help="plot a run trace: controller phase, gripper status, held height, force")
    plot.add_argument("trace", help="trace file written by graphflow run --trace")
    plot.add_argument("-o", "--output", required=True, metavar="FILE", help="image file (.png, .svg or .pdf)")
    plot.add_argument("--force", action="store_true", help="overwrite an existing image")
    plot.set_defaults(handler=command_plot)


def command_trace_diff(args) -> int:
    from graphflow.observe.trace import first_difference, read_trace

    left, right = read_trace(args.left), read_trace(args.right)
    if args.tolerance is not None:
        from graphflow.observe.trace_tolerance import read_tolerances, tolerant_difference

        divergence = tolerant_difference(left, right, read_tolerances(args.tolerance or None))
        if divergence is None:
            print(f"traces match within tolerance ({len(left.ticks)} ticks)")
            return EXIT_OK
        print(divergence.describe(args.left, args.right))
        return EXIT_TRACES_DIFFER
    difference = first_difference(left, right)
    if difference is None:
        print(f"traces are identical ({len(left.ticks)} ticks)")
        return EXIT_OK
    print(difference.describe(args.left, args.right))
    return EXIT_TRACES_DIFFER


def command_draw(args) -> int:
    from graphflow.observe import draw

    document = load_document(args.graph)
    try:
        picture_format = draw.format_for(args.output, args.format)
    except ValueError as error:
        raise BadInput(str(error)) from None
    if picture_format == "png":
        require_extra("draw --format png", "viz", "matplotlib")
    try:
        with atomic_output(args.output, force=args.force) as temporary:
            draw.write(draw.layout(document), temporary, picture_format)
    except OSError as error:
        raise BadInput(f"{args.output}: cannot write the picture: {error.strerror or error}") from None
    print(f"wrote {args.output}")
    return EXIT_OK


def command_plot(args) -> int:
    require_extra("plot", "viz", "matplotlib")
    from graphflow.observe.timeline import write_timeline
    from graphflow.observe.trace import read_trace

    trace = read_trace(args.trace)
    try:
        with atomic_output(args.output, force=args.force) as temporary:
            drawn = write_timeline(trace, temporary)
    except BadInput:
        raise
    except (OSError, ValueError) as error:
        raise BadInput(f"{args.output}: cannot write the plot: {error}") from None
    for note in drawn.notes:
        print(f"note: {note}")
    print(f"wrote {args.output}")
    return EXIT_OK
