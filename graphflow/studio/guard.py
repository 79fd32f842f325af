"""The studio's protection, as one ASGI middleware in front of every request and websocket.

A server that writes files and runs graphs is an attack surface even on a laptop: a web page in
another tab can send requests to 127.0.0.1 (cross-site requests) or rebind its own host name to
127.0.0.1 (DNS rebinding). So every request must carry the session's random token (in the URL, as
Jupyter does, or the ``X-Graphflow-Token`` header), name one of the studio's own hosts in ``Host``,
come from the studio's own page when it says where it comes from (``Origin``), and stay under the
body limit. A refusal is a JSON error; no request, good or bad, can stop the server.
"""
from __future__ import annotations

import json
import logging
import secrets
from http import HTTPStatus
from urllib.parse import parse_qs

logger = logging.getLogger(__name__)

TOKEN_HEADER = b"x-graphflow-token"
DEFAULT_BODY_LIMIT = 4 * 1024 * 1024    # a 36-node graph is ~20 kB; a stage is never uploaded


class BodyTooLarge(Exception):
    """The request's body grew past the limit while it was being read."""


def new_token() -> str:
    """A random URL-safe token (256 bits), one per server."""
    return secrets.token_urlsafe(32)


def local_hosts(port: int, host: str = "127.0.0.1") -> set[str]:
    """The ``Host`` values a browser sends for the studio: the loopback names with the port (and the bound host)."""
    names = {"127.0.0.1", "localhost", "[::1]", host if ":" not in host else f"[{host}]"}
    return {f"{name}:{port}" for name in names}


async def send_json_error(send, status: int, message: str) -> None:
    """A refusal as JSON: ``{"error": message}`` with *status*."""
    body = json.dumps({"error": message, "status": status}).encode()
    await send({"type": "http.response.start", "status": status,
                "headers": [(b"content-type", b"application/json"), (b"content-length", str(len(body)).encode())]})
    await send({"type": "http.response.body", "body": body})


class Guard:
    """ASGI middleware: token, Host, Origin and body-size checks, and a JSON 500 for any uncaught error."""

    def __init__(self, app, *, token: str, hosts: set[str], body_limit: int = DEFAULT_BODY_LIMIT):
        self.app, self.token, self.hosts, self.body_limit = app, token, hosts, body_limit

    async def __call__(self, scope, receive, send):
        if scope["type"] not in ("http", "websocket"):
            return await self.app(scope, receive, send)
        refusal = self.refusal(scope)
        if refusal is not None:
            status, message = refusal
            logger.warning("refused %s %s: %s", scope.get("method", "WS"), scope.get("path"), message)
            if scope["type"] == "websocket":
                await receive()                                  # the websocket.connect event
                return await send({"type": "websocket.close", "code": 1008, "reason": message[:120]})
            return await send_json_error(send, status, message)
        if scope["type"] == "websocket":
            return await self.app(scope, receive, send)
        await self._http(scope, receive, send)

    def refusal(self, scope) -> tuple[int, str] | None:
        """Why this request is refused (status, message), or None."""
        headers = {name.decode("latin-1").lower(): value.decode("latin-1") for name, value in scope.get("headers", [])}
        host = headers.get("host", "")
        if host not in self.hosts:
            return HTTPStatus.FORBIDDEN, f"Host {host!r} is not this studio's (DNS rebinding?): open the URL graphflow studio printed"
        origin = headers.get("origin")
        if origin is not None and origin not in {f"http://{allowed}" for allowed in self.hosts}:
            return HTTPStatus.FORBIDDEN, f"Origin {origin!r} is not this studio's page: cross-site requests are refused"
        given = headers.get(TOKEN_HEADER.decode()) or _query_token(scope)
        if not given or not secrets.compare_digest(given.encode(), self.token.encode()):
            return HTTPStatus.FORBIDDEN, "missing or wrong token: open the URL graphflow studio printed (it ends in ?token=...)"
        declared = headers.get("content-length")
        if declared is not None and (not declared.isdigit() or int(declared) > self.body_limit):
            return HTTPStatus.REQUEST_ENTITY_TOO_LARGE, f"request body over the studio's limit of {self.body_limit} bytes"
        return None

    async def _http(self, scope, receive, send):
        received, started = 0, False

        async def limited_receive():
            nonlocal received
            message = await receive()
            if message["type"] == "http.request":
                received += len(message.get("body", b""))
                if received > self.body_limit:
                    raise BodyTooLarge
            return message

        async def tracking_send(message):
            nonlocal started
            if message["type"] == "http.response.start":
                started = True
            await send(message)

        try:
            await self.app(scope, limited_receive, tracking_send)
        except BodyTooLarge:
            if not started:
                await send_json_error(send, HTTPStatus.REQUEST_ENTITY_TOO_LARGE,
                                      f"request body over the studio's limit of {self.body_limit} bytes")
        except Exception as error:   # a bug in a handler: answer, log, keep serving
            logger.exception("studio request %s failed", scope.get("path"))
            if not started:
                await send_json_error(send, HTTPStatus.INTERNAL_SERVER_ERROR, f"internal error: {error}")


def _query_token(scope) -> str | None:
    values = parse_qs(scope.get("query_string", b"").decode("latin-1")).get("token")
    return values[0] if values else None
