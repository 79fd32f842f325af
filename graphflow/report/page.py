"""The report file: the committed page bundle with the run's data embedded as JSON (no network, no server)."""
from __future__ import annotations

import json
from importlib import resources

from graphflow.files import write_text

DATA_MARK = "<!--graphflow-run-data-->"


def bundle_text() -> str:
    """The built page (frontend/ through Vite, JS and CSS inlined), shipped as package data."""
    return resources.files("graphflow.report").joinpath("bundle/report.html").read_text(encoding="utf-8")


def _script_safe(text: str) -> str:
    """JSON that cannot end its <script> element or open a comment inside it."""
    return text.replace("</", "<\\/").replace("<!--", "<\\u0021--")


def render_report(data: dict) -> str:
    """The whole HTML page for one run's data; the same data gives the same bytes."""
    payload = _script_safe(json.dumps(data, separators=(",", ":"), ensure_ascii=False, allow_nan=True))
    page = bundle_text()
    if DATA_MARK not in page:
        raise RuntimeError("graphflow/report/bundle/report.html has no data mark: rebuild it (cd frontend && npm run build)")
    script = f'<script id="graphflow-run" type="application/json">{payload}</script>'
    return page.replace(DATA_MARK, script, 1)


def write_report(data: dict, path, *, force: bool = False) -> None:
    """Write the report atomically (graphflow.files): an existing file only with *force*."""
    write_text(path, render_report(data), force=force)
