"""The studio's protections, each tried with a real HTTP request to a running server on 127.0.0.1."""
import os
import socket

import pytest


def test_the_page_and_the_api_answer_with_the_token(studio):
    status, page = studio.request("GET", "/")
    assert status == 200 and 'id="graphflow-studio"' in page and studio.token in page
    status, info = studio.request("GET", "/api/info")
    assert status == 200 and info["opened"] == "counter.json" and "counter.json" in info["files"]


@pytest.mark.parametrize("path", ["/", "/api/info", "/api/graph?path=counter.json", "/api/forms", "/api/stages?path=counter.json",
                                  "/api/prims?path=counter.json&stage=asset:ur10.usda"])
def test_a_request_without_the_token_is_refused(studio, path):
    status, body = studio.request("GET", path, token=False)
    assert status == 403 and "token" in body["error"]


def test_a_wrong_token_is_refused_in_the_url_and_in_the_header(studio):
    status, body = studio.request("GET", "/api/info?token=" + "x" * len(studio.token), token=False)
    assert status == 403 and "token" in body["error"]
    status, _ = studio.request("GET", "/api/info", token=False, headers={"X-Graphflow-Token": "nope"})
    assert status == 403
    status, _ = studio.request("GET", "/api/info", token=False, headers={"X-Graphflow-Token": studio.token})
    assert status == 200


def test_a_foreign_host_is_refused_even_with_the_token(studio):
    """DNS rebinding: a page on evil.example whose name now resolves to 127.0.0.1 sends Host: evil.example."""
    status, body = studio.request("GET", "/api/info", headers={"Host": f"evil.example:{studio.port}"})
    assert status == 403 and "Host" in body["error"]
    status, _ = studio.request("GET", "/api/info", headers={"Host": f"localhost:{studio.port}"})
    assert status == 200


def test_a_cross_site_origin_is_refused(studio, studio_folder):
    before = (studio_folder / "counter.json").read_bytes()
    status, body = studio.request("POST", "/api/save", {"path": "counter.json", "data": {}},
                                  headers={"Origin": "http://evil.example", "Content-Type": "application/json"})
    assert status == 403 and "Origin" in body["error"]
    assert (studio_folder / "counter.json").read_bytes() == before
    status, _ = studio.request("GET", "/api/info", headers={"Origin": f"http://127.0.0.1:{studio.port}"})
    assert status == 200


@pytest.mark.parametrize("path", ["../outside.json", "/etc/passwd", "sub/../../outside.json", "a\\..\\b.json"])
def test_paths_outside_the_served_folder_are_refused(studio, path):
    status, body = studio.request("GET", f"/api/graph?path={path}")
    assert status == 400 and "served folder" in body["error"]


def test_a_symbolic_link_out_of_the_folder_is_refused(studio, studio_folder, tmp_path_factory):
    outside = tmp_path_factory.mktemp("outside") / "secret.json"
    outside.write_text('{"secret": 1}\n')
    os.symlink(outside, studio_folder / "link.json")
    status, body = studio.request("GET", "/api/graph?path=link.json")
    assert status == 400 and "outside the served folder" in body["error"]
    status, body = studio.request("POST", "/api/save", {"path": "link.json", "data": {"secret": 2}, "revision": None})
    assert status == 400 and outside.read_text() == '{"secret": 1}\n'


def test_a_body_over_the_limit_is_refused_and_the_server_keeps_serving(studio):
    status, body = studio.request("POST", "/api/check", b"x" * (5 * 1024 * 1024), headers={"Content-Type": "application/json"})
    assert status == 413 and "limit" in body["error"]
    assert studio.request("GET", "/api/info")[0] == 200


@pytest.mark.parametrize("body", [b"{not json", b"[1, 2]", b"\xff\xfe"])
def test_a_bad_body_gets_a_clear_json_error_and_the_server_keeps_serving(studio, body):
    status, answer = studio.request("POST", "/api/check", body)
    assert status == 400 and "JSON" in answer["error"]
    assert studio.request("GET", "/api/info")[0] == 200


def test_unknown_routes_and_methods_are_json_errors(studio):
    assert studio.request("GET", "/api/nothing")[0] == 404
    status, body = studio.request("GET", "/api/save")
    assert status == 405 and "GET" in body["error"]


def test_ctrl_c_stops_the_server_with_exit_130(studio):
    assert studio.stop() == 130


def test_the_server_listens_on_loopback_only(studio):
    """Its socket is bound to 127.0.0.1: the machine's other addresses do not reach it."""
    addresses = {info[4][0] for info in socket.getaddrinfo(socket.gethostname(), None, socket.AF_INET)} - {"127.0.0.1"}
    addresses = {address for address in addresses if not address.startswith("127.")}
    if not addresses:
        pytest.skip("this machine has no IPv4 address but loopback")
    for address in addresses:
        with pytest.raises(OSError):
            socket.create_connection((address, studio.port), timeout=5).close()
    assert studio.host == "127.0.0.1"
