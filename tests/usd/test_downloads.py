"""The download cache: http(s) assets fetched once from a server (here one on 127.0.0.1, never the
internet) into a folder that keeps the URL's layout; what cannot be fetched is one line saying why."""
import functools
import http.server
import shutil
import threading

import pytest
from conftest import ROOT

from graphflow.usd.errors import StageError
from graphflow.usd.opening import missing_layers_refused, open_composed

PACKAGED = ROOT / "graphflow" / "assets"


class QuietHandler(http.server.SimpleHTTPRequestHandler):
    requests: list[str] = []

    def log_message(self, *args):   # the test's output is the test's
        pass

    def do_GET(self):
        QuietHandler.requests.append(self.path)
        super().do_GET()


@pytest.fixture
def server(tmp_path):
    """A folder served on 127.0.0.1: Isaac/Robots/ur10/ur10.usd (the packaged UR10) and a cell layer beside it."""
    site = tmp_path / "site"
    robot = site / "Isaac" / "Robots" / "ur10"
    robot.mkdir(parents=True)
    shutil.copy(PACKAGED / "ur10.usda", robot / "ur10.usd")
    (site / "Isaac" / "cell.usda").write_text('#usda 1.0\n(\n    defaultPrim = "Cell"\n)\n'
                                              'def Xform "Cell" (prepend references = @./Robots/ur10/ur10.usd@)\n{\n}\n')
    QuietHandler.requests = []
    httpd = http.server.ThreadingHTTPServer(("127.0.0.1", 0), functools.partial(QuietHandler, directory=str(site)))
    thread = threading.Thread(target=httpd.serve_forever, daemon=True)
    thread.start()
    yield f"http://127.0.0.1:{httpd.server_address[1]}"
    httpd.shutdown()
    httpd.server_close()
    thread.join()


def user_stage(tmp_path, url):
    stage = tmp_path / "project" / "scene.usda"
    stage.parent.mkdir()
    stage.write_text(f'#usda 1.0\ndef Xform "World"\n{{\n    def Xform "cell" (prepend references = @{url}@)\n    {{\n    }}\n}}\n')
    return stage


def test_a_url_and_the_relative_layers_it_names_are_fetched_once_into_the_cache(server, tmp_path, monkeypatch):
    cache = tmp_path / "cache"
    monkeypatch.setenv("GRAPHFLOW_ASSET_CACHE", str(cache))
    stage_file = user_stage(tmp_path, f"{server}/Isaac/cell.usda")
    with missing_layers_refused():
        stage = open_composed(stage_file)
    assert stage.GetPrimAtPath("/World/cell/ee_link/SurfaceGripper").IsValid()
    host = server.split("//")[1].replace(":", "_")
    assert (cache / host / "Isaac" / "Robots" / "ur10" / "ur10.usd").read_bytes() == (PACKAGED / "ur10.usda").read_bytes()
    assert sorted(QuietHandler.requests) == ["/Isaac/Robots/ur10/ur10.usd", "/Isaac/cell.usda"]
    with missing_layers_refused():
        open_composed(stage_file)   # a second open reads the cache
    assert len(QuietHandler.requests) == 2


def test_what_cannot_be_fetched_is_one_line_saying_why(server, tmp_path, monkeypatch):
    monkeypatch.setenv("GRAPHFLOW_ASSET_CACHE", str(tmp_path / "cache"))
    stage_file = user_stage(tmp_path, f"{server}/Isaac/missing.usd")
    with missing_layers_refused(), pytest.raises(StageError) as caught:
        open_composed(stage_file)
    assert caught.value.problems == [
        f"{stage_file}: cannot open {server}/Isaac/missing.usd, the reference of /World/cell in layer scene.usda: "
        "prims lost: everything that reference puts below /World/cell (download failed: File not found)"]


def test_without_a_cache_folder_nothing_is_fetched(server, tmp_path, monkeypatch):
    monkeypatch.delenv("GRAPHFLOW_ASSET_CACHE", raising=False)
    stage_file = user_stage(tmp_path, f"{server}/Isaac/cell.usda")
    with missing_layers_refused(), pytest.raises(StageError, match="map its URL prefix to a local folder"):
        open_composed(stage_file)
    assert QuietHandler.requests == []


def test_the_project_file_names_the_cache_folder_relative_to_itself(server, tmp_path, monkeypatch):
    monkeypatch.delenv("GRAPHFLOW_ASSET_CACHE", raising=False)
    stage_file = user_stage(tmp_path, f"{server}/Isaac/Robots/ur10/ur10.usd")
    (stage_file.parent / "graphflow.toml").write_text('[assets]\ncache = ".asset-cache"\n')
    with missing_layers_refused():
        assert open_composed(stage_file).GetPrimAtPath("/World/cell/ee_link").IsValid()
    assert list((stage_file.parent / ".asset-cache").rglob("ur10.usd"))
