"""Starting and stopping the studio's server: one loopback socket, uvicorn, the URL with its token."""
from __future__ import annotations

import logging
import socket
import sys
import webbrowser
from pathlib import Path

from graphflow.errors import BadInput, require_extra

LOOPBACK = "127.0.0.1"


def bind(host: str, port: int) -> socket.socket:
    """The listening socket, bound before the server starts so the URL (and the allowed Host) names its real port."""
    family = socket.AF_INET6 if ":" in host else socket.AF_INET
    listener = socket.socket(family, socket.SOCK_STREAM)
    listener.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
    try:
        listener.bind((host, port))
    except OSError as error:
        listener.close()
        raise BadInput(f"cannot listen on {host}:{port}: {error.strerror}") from None
    listener.listen(64)
    return listener


def url_of(host: str, port: int, token: str) -> str:
    shown = LOOPBACK if host in (LOOPBACK, "0.0.0.0") else (f"[{host}]" if ":" in host else host)
    return f"http://{shown}:{port}/?token={token}"


def serve(target: str | None, *, host: str = LOOPBACK, port: int = 0, open_browser: bool = True,
          token: str | None = None, announce=print) -> None:
    """Serve the studio on *target* (a graph file or a folder) until Ctrl-C (``KeyboardInterrupt`` to the caller)."""
    require_extra("graphflow studio", "studio", "starlette", "uvicorn", "websockets")
    import uvicorn

    from graphflow.studio.app import Session, build_app
    from graphflow.studio.folder import ServedFolder
    from graphflow.studio.guard import local_hosts, new_token

    chosen = Path(target or ".").resolve()
    if not chosen.exists():
        raise BadInput(f"{target}: no such graph file or folder")
    folder = ServedFolder(chosen if chosen.is_dir() else chosen.parent)
    session = Session(folder, token or new_token(), None if chosen.is_dir() else folder.relative(chosen))
    if host != LOOPBACK:
        print(f"warning: graphflow studio listens on {host}: anyone who can reach it and learns the token "
              "can edit files under the folder and run graphs", file=sys.stderr)
    listener = bind(host, port)
    actual_port = listener.getsockname()[1]
    app = build_app(session, local_hosts(actual_port, host))
    url = url_of(host, actual_port, session.token)
    announce(f"graphflow studio serving {folder.root} at {url}")
    if open_browser:
        webbrowser.open(url)
    config = uvicorn.Config(app, log_level="warning", ws="websockets-sansio", lifespan="off",
                            ws_max_size=1024 * 1024, timeout_graceful_shutdown=2)
    logging.getLogger("uvicorn.error").setLevel(logging.WARNING)
    uvicorn.Server(config).run(sockets=[listener])
