"""``graphflow studio [GRAPH.json | DIR]``: the browser studio (docs/studio.md), on 127.0.0.1 with a token."""
from __future__ import annotations

from graphflow.errors import EXIT_INTERRUPTED


def register(commands) -> None:
    studio = commands.add_parser(
        "studio", help="edit, validate and run graphs in the browser (local server: pip install 'graphflow[studio]')")
    studio.add_argument("target", nargs="?", default=".", metavar="GRAPH.json | DIR",
                        help="graph file to open, or the folder to serve (default: the current folder)")
    studio.add_argument("--no-browser", action="store_true", help="print the URL instead of opening a browser")
    studio.add_argument("--port", type=int, default=0, help="port to listen on (default: a free one)")
    studio.add_argument("--listen", default="127.0.0.1", metavar="ADDRESS",
                        help="address to listen on; anything but 127.0.0.1 exposes the studio to the network (warned)")
    studio.set_defaults(handler=command_studio)


def command_studio(args) -> int:
    from graphflow.studio.server import serve

    serve(args.target, host=args.listen, port=args.port, open_browser=not args.no_browser,
          announce=lambda line: print(line, flush=True))
    return EXIT_INTERRUPTED   # the server only stops on Ctrl-C or SIGTERM (uvicorn re-raises it after shutting down)
