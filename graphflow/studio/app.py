"""The studio's HTTP routes (Starlette): the page, the palette, opening, checking and saving graphs.

Every route is behind ``guard.Guard`` (token, Host, Origin, body size). Errors the user can fix
(a path outside the folder, a body that is not JSON) are answered 400 with ``{"error": ...}``.
"""
from __future__ import annotations

import asyncio
import json
from dataclasses import dataclass
from functools import lru_cache

from starlette.applications import Starlette
from starlette.requests import Request
from starlette.responses import HTMLResponse, JSONResponse
from starlette.routing import Route, WebSocketRoute
from starlette.websockets import WebSocket, WebSocketDisconnect

from graphflow.errors import BadInput
from graphflow.studio import editing
from graphflow.studio.folder import ServedFolder
from graphflow.studio.guard import Guard

STUDIO_MARK = "<!--graphflow-run-data-->"   # the bundle's data mark (graphflow.report.page): studio mode instead


@dataclass
class Session:
    """One server's state: its folder, the graph it opened first, and its token."""

    folder: ServedFolder
    token: str
    opened: str | None = None


def _page(session: Session) -> str:
    from graphflow.report.page import bundle_text

    config = json.dumps({"mode": "studio", "token": session.token, "file": session.opened}).replace("<", "\\u003c")
    # the icon link keeps the browser from asking for /favicon.ico, which the guard would refuse (no token)
    script = f'<link rel="icon" href="data:,"><script id="graphflow-studio" type="application/json">{config}</script>'
    return bundle_text().replace(STUDIO_MARK, script, 1)


@lru_cache(maxsize=1)
def _palette() -> dict:
    return editing.palette()


async def _body(request: Request) -> dict:
    try:
        body = json.loads(await request.body())
    except (ValueError, UnicodeDecodeError):
        raise BadInput("the request body is not JSON") from None
    if not isinstance(body, dict):
        raise BadInput("the request body must be a JSON object")
    return body


async def stream_live(websocket: WebSocket, path, folder) -> None:
    """Run *path* live for one page: its commands in, the run's frames out, until the page goes."""
    from graphflow.report.build import json_safe  # NaN and infinities as the report writes them
    from graphflow.studio.frames import Outbox
    from graphflow.studio.live import LiveRun, report_path

    loop, outbox = asyncio.get_running_loop(), Outbox()
    run = LiveRun(path, lambda message: loop.call_soon_threadsafe(outbox.put, message))

    async def send_frames():
        while True:
            message = await outbox.take()
            await websocket.send_text(json.dumps(json_safe(message), separators=(",", ":")))

    sender = asyncio.create_task(send_frames())
    try:
        while True:
            try:
                message = json.loads(await websocket.receive_text())
                _live_message(run, message, folder, report_path)
            except (ValueError, BadInput, KeyError, TypeError) as error:
                outbox.put({"type": "error", "message": f"bad live message: {error}"})
    except WebSocketDisconnect:
        pass
    finally:
        sender.cancel()
        await asyncio.to_thread(run.close)


LIVE_COMMANDS = {"play", "pause", "step", "reset", "speed"}


def _live_message(run, message, folder, report_path) -> None:
    """One message of the page: a run command, a key, a gamepad control, a mouse event, or a save-as."""
    if not isinstance(message, dict):
        raise BadInput("a live message is a JSON object")
    if "key" in message:
        run.keys.press(message["key"], bool(message.get("down")))
    elif "pad" in message:
        run.pad.move(message["pad"], message.get("value"))
    elif "mouse" in message:
        run.mouse.event(message["mouse"], message.get("value"))
    elif message.get("command") in LIVE_COMMANDS:
        run.command(message["command"], value=message.get("value"))
    elif message.get("command") in ("saveReport", "saveTrace"):
        run.command(message["command"], path=report_path(folder, message.get("path", "")))
    else:
        raise BadInput(f"unknown live message {json.dumps(message)[:80]}")


def build_app(session: Session, hosts: set[str]) -> Guard:
    """The ASGI application: the routes behind the guard."""

    async def page(request: Request):
        return HTMLResponse(_page(session), headers={"Cache-Control": "no-store", "Referrer-Policy": "no-referrer"})

    async def info(request: Request):
        return JSONResponse({"folder": str(session.folder.root), "opened": session.opened,
                             "files": session.folder.graph_files()})

    async def palette(request: Request):
        return JSONResponse(_palette())

    async def open_graph(request: Request):
        path = session.folder.resolve(request.query_params.get("path", ""))
        opened = editing.read_graph(path)
        return JSONResponse({"path": session.folder.relative(path), "layout": editing.drawn_layout(opened["data"], path),
                             **opened})

    watching: dict = {}   # graph path -> graphflow.watching.WatchedFiles, kept between the page's polls

    async def watched(request: Request):
        from graphflow.watching import WatchedFiles, graph_files

        path = session.folder.resolve(request.query_params.get("path", ""))
        if path not in watching:   # off the event loop: the first look opens the stage's layers
            watching[path] = await asyncio.to_thread(WatchedFiles, lambda: graph_files(path))
        return JSONResponse(await asyncio.to_thread(editing.watched_revision, path, watching[path]))

    async def check(request: Request):
        body = await _body(request)
        path = session.folder.resolve(body.get("path", ""))
        problems, _document = editing.check(body.get("data"), path)
        return JSONResponse({"problems": [editing.problem_json(p) for p in problems]})

    async def save(request: Request):
        body = await _body(request)
        path = session.folder.resolve(body.get("path", ""))
        outcome = editing.save(body.get("data"), path, opened_revision=body.get("revision"),
                               replace_valid=bool(body.get("replaceValid")))
        status = 200 if outcome.status == "saved" else 409
        return JSONResponse({"status": outcome.status, "revision": outcome.revision,
                             "problems": list(outcome.problems), "difference": outcome.difference}, status_code=status)

    async def forms(request: Request):
        return JSONResponse(editing.document_forms())

    async def prims(request: Request):
        from graphflow.studio.stage_prims import stage_prims

        path = session.folder.resolve(request.query_params.get("path", ""))
        return JSONResponse(await asyncio.to_thread(stage_prims, request.query_params.get("stage", ""), path,
                                                    session.folder.root))

    async def stages(request: Request):
        from graphflow.studio.stage_prims import stage_choices

        path = session.folder.resolve(request.query_params.get("path", ""))
        return JSONResponse({"stages": await asyncio.to_thread(stage_choices, path, session.folder.root)})

    async def bad_input(request: Request, error: Exception):     # Starlette calls it for BadInput only
        return JSONResponse({"error": str(error), "status": 400}, status_code=400)

    async def not_found(request: Request, error):
        return JSONResponse({"error": f"no such studio route: {request.url.path}", "status": 404}, status_code=404)

    async def wrong_method(request: Request, error):
        return JSONResponse({"error": f"{request.method} is not allowed on {request.url.path}", "status": 405},
                            status_code=405)

    async def live(websocket: WebSocket):
        await websocket.accept()
        try:
            path = session.folder.resolve(websocket.query_params.get("path", ""))
        except BadInput as error:
            await websocket.send_json({"type": "error", "message": str(error)})
            return await websocket.close(code=1008)
        await stream_live(websocket, path, session.folder)

    routes = [Route("/", page), WebSocketRoute("/api/live", live), Route("/api/info", info), Route("/api/palette", palette),
              Route("/api/graph", open_graph), Route("/api/forms", forms), Route("/api/prims", prims),
              Route("/api/stages", stages), Route("/api/revision", watched), Route("/api/check", check, methods=["POST"]),
              Route("/api/save", save, methods=["POST"])]
    app = Starlette(routes=routes, exception_handlers={BadInput: bad_input, 404: not_found, 405: wrong_method})
    return Guard(app, token=session.token, hosts=hosts)
