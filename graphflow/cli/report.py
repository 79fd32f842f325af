"""``graphflow report TRACE -o FILE.html``: the offline run report of a trace written earlier (docs/report.md)."""
from __future__ import annotations

from graphflow.document import load_document
from graphflow.errors import EXIT_OK, BadInput
from graphflow.files import refuse_existing


def register(commands) -> None:
    report = commands.add_parser("report", help="make the HTML run report of a trace (graphflow run --trace)")
    report.add_argument("trace", help="trace file written by graphflow run --trace")
    report.add_argument("-o", "--output", required=True, metavar="FILE.html", help="report file to write")
    report.add_argument("--graph", help="graph file the trace ran (default: the one its header names)")
    report.add_argument("--force", action="store_true", help="overwrite an existing report")
    report.set_defaults(handler=command_report)


def command_report(args) -> int:
    from graphflow.observe.trace import read_trace
    from graphflow.report.recording import from_trace

    refuse_existing(args.output, args.force)
    trace = read_trace(args.trace)
    graph = args.graph or trace.header.get("graph")
    if not graph:
        raise BadInput(f"{args.trace}: the trace names no graph file; give it with --graph")
    from_trace(trace, load_document(graph), args.output, force=args.force)
    print(f"wrote {args.output}")
    return EXIT_OK
