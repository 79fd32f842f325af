"""A studio server per test module: ``graphflow studio --no-browser`` on a copy of a shipped graph, in a subprocess."""
import http.client
import json
import shutil
import signal
import subprocess
import sys
from pathlib import Path
from urllib.parse import urlsplit

import pytest

pytest.importorskip("starlette", reason="graphflow studio needs the studio extra: pip install -e '.[studio]'")
pytest.importorskip("uvicorn")

GRAPHS = Path(__file__).resolve().parents[2] / "graphs"


class Studio:
    """A running ``graphflow studio`` and plain HTTP requests to it (http.client: every header is ours to set)."""

    def __init__(self, folder: Path, opened: str):
        self.folder = folder
        self.process = subprocess.Popen([sys.executable, "-m", "graphflow", "studio", str(folder / opened), "--no-browser"],
                                        stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        line = self.process.stdout.readline()
        if "http://" not in line:
            self.process.kill()
            raise AssertionError(f"the studio did not start: {line}{self.process.stderr.read()}")
        self.url = line.split(" at ", 1)[1].strip()
        parts = urlsplit(self.url)
        self.host, self.port, self.token = parts.hostname, parts.port, parts.query.split("=", 1)[1]

    def request(self, method, path, body=None, *, token=True, headers=None):
        """(status, parsed JSON or text) of one request; the token goes in the URL unless *token* is False."""
        connection = http.client.HTTPConnection(self.host, self.port, timeout=60)
        separator = "&" if "?" in path else "?"
        target = f"{path}{separator}token={self.token}" if token else path
        data = json.dumps(body).encode() if isinstance(body, (dict, list)) else body
        connection.request(method, target, body=data, headers=headers or {})
        response = connection.getresponse()
        text = response.read().decode()
        connection.close()
        kind = response.getheader("content-type") or ""
        return response.status, (json.loads(text) if kind.startswith("application/json") else text)

    def stop(self) -> int:
        self.process.send_signal(signal.SIGINT)
        try:
            return self.process.wait(timeout=30)
        finally:
            self.process.stdout.close()
            self.process.stderr.close()


@pytest.fixture
def studio_folder(tmp_path):
    """A folder holding a copy of graphs/counter_branch_print.json (the studio edits the copy)."""
    shutil.copy(GRAPHS / "counter_branch_print.json", tmp_path / "counter.json")
    return tmp_path


@pytest.fixture
def studio(studio_folder):
    server = Studio(studio_folder, "counter.json")
    yield server
    if server.process.poll() is None:
        server.stop()
