"""The studio's HTTP routes (Starlette): the page, the palette, opening, checking and saving graphs.

Every route is behind ``guard.Guard`` (token, Host, Origin, body size). Errors the user can fix
(a path outside the folder, a body that is not JSON) are answered 400 with ``{"error": ...}``.
"""
from __future__ import annotations

import json
from dataclasses import dataclass
from functools import lru_cache

from starlette.applications import Starlette
from starlette.requests import Request
from starlette.responses import HTMLResponse, JSONResponse
from starlette.routing import Route

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
    script = f'<script id="graphflow-studio" type="application/json">{config}</script>'
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
        return JSONResponse({"path": session.folder.relative(path), **editing.read_graph(path)})

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

    async def bad_input(request: Request, error: BadInput):
        return JSONResponse({"error": str(error), "status": 400}, status_code=400)

    async def not_found(request: Request, error):
        return JSONResponse({"error": f"no such studio route: {request.url.path}", "status": 404}, status_code=404)

    async def wrong_method(request: Request, error):
        return JSONResponse({"error": f"{request.method} is not allowed on {request.url.path}", "status": 405},
                            status_code=405)

    routes = [Route("/", page), Route("/api/info", info), Route("/api/palette", palette),
              Route("/api/graph", open_graph), Route("/api/check", check, methods=["POST"]),
              Route("/api/save", save, methods=["POST"])]
    app = Starlette(routes=routes, exception_handlers={BadInput: bad_input, 404: not_found, 405: wrong_method})
    return Guard(app, token=session.token, hosts=hosts)
