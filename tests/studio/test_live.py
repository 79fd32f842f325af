"""A live run over the studio's websocket: steps, keys from the page feeding OnKeyboardInput, frames, the saved trace."""
import json
import shutil

import pytest

from graphflow.observe.trace import read_trace

from .conftest import GRAPHS, Studio

websockets_sync = pytest.importorskip("websockets.sync.client")

Y_STEP = 0.005   # the gantry graph's y_step.inputs:b: metres of drive target per tick while Up is held


@pytest.fixture
def gantry(tmp_path):
    for name in ("gantry_keyboard.json", "gantry_keyboard.keys.json"):
        shutil.copy(GRAPHS / name, tmp_path / name)
    server = Studio(tmp_path, "gantry_keyboard.json")
    yield server
    server.stop()


def connect(studio, *, token=True, origin=None):
    query = f"path=gantry_keyboard.json&token={studio.token}" if token else "path=gantry_keyboard.json"
    return websockets_sync.connect(f"ws://127.0.0.1:{studio.port}/api/live?{query}", origin=origin, open_timeout=30)


def until(socket, kind, predicate=lambda message: True):
    while True:
        message = json.loads(socket.recv(timeout=120))
        assert message["type"] != "error", message
        if message["type"] == kind and predicate(message):
            return message


def step(socket, ticks):
    """Step *ticks* ticks one at a time (each step answers with one frame); the outputs that changed, merged."""
    changed, grippers = {}, {}
    for _ in range(ticks):
        socket.send(json.dumps({"command": "step"}))
        frame = until(socket, "frame")
        changed.update(frame["outputs"])
        for path, fields in frame["grippers"].items():
            grippers.setdefault(path, {}).update(fields)
    return frame, changed, grippers


def test_keys_pressed_in_the_page_move_the_joint_target_and_close_the_gripper(gantry):
    with connect(gantry) as socket:
        until(socket, "start")
        frame, before, _ = step(socket, 5)
        assert frame["tick"] == 5
        y_start = before["y_target.value"]
        socket.send(json.dumps({"key": "ArrowUp", "down": True}))
        step(socket, 10)
        socket.send(json.dumps({"key": "ArrowUp", "down": False}))
        _, changed, _ = step(socket, 3)
        y_now = changed["y_target.value"]   # the page sees the target read back after the last write
        assert y_now - y_start == pytest.approx(10 * Y_STEP, abs=1e-12)   # held for 10 ticks: 10 steps of 5 mm
        socket.send(json.dumps({"key": "KeyA", "down": True}))
        socket.send(json.dumps({"key": "KeyA", "down": False}))
        _, _, grippers = step(socket, 5)
        assert any(fields.get("status") in ("Closing", "Closed") for fields in grippers.values()), grippers
        socket.send(json.dumps({"command": "saveTrace", "path": "live.jsonl"}))
        until(socket, "saved")
    trace = read_trace(gantry.folder / "live.jsonl")
    ys = [value for _time, value in trace.series("y_target.value")]
    assert max(ys) == y_now and ys[-1] == y_now
    statuses = {value for path in trace.gripper_paths for _t, value in trace.gripper_series(path, "status")}
    assert statuses & {"Closing", "Closed"}


def test_playing_at_max_speed_streams_at_most_about_30_frames_a_second(gantry):
    with connect(gantry) as socket:
        until(socket, "start")
        socket.send(json.dumps({"command": "speed", "value": None}))
        socket.send(json.dumps({"command": "play"}))
        frames = []
        while True:
            frame = until(socket, "frame")
            frames.append(frame)
            if frame["tick"] >= 600:
                break
        socket.send(json.dumps({"command": "pause"}))
        until(socket, "frame", lambda message: not message["playing"])
    ticks_per_frame = 600 / len(frames)
    assert ticks_per_frame > 1   # never a message per tick


def test_a_bad_live_message_is_an_error_message_and_the_run_goes_on(gantry):
    with connect(gantry) as socket:
        until(socket, "start")
        socket.send("not json")
        assert "bad live message" in json.loads(socket.recv(timeout=60))["message"]
        socket.send(json.dumps({"key": "NoSuchKey", "down": True}))
        assert "OnKeyboardInput" in json.loads(socket.recv(timeout=60))["message"]
        socket.send(json.dumps({"command": "saveReport", "path": "../escape.html"}))
        assert "served folder" in json.loads(socket.recv(timeout=60))["message"]
        frame, _, _ = step(socket, 1)
        assert frame["tick"] == 1


def test_the_live_stream_refuses_a_missing_token_and_a_foreign_origin(gantry):
    from websockets.exceptions import InvalidStatus

    for options in ({"token": False}, {"origin": "http://evil.example"}):
        with pytest.raises(InvalidStatus) as refused:
            connect(gantry, **options)
        assert refused.value.response.status_code == 403


@pytest.fixture
def pick_place(tmp_path):
    shutil.copy(GRAPHS / "ur10_pick_place.json", tmp_path / "pick.json")
    server = Studio(tmp_path.resolve(), "pick.json")
    yield server
    server.stop()


def test_a_live_run_saves_the_trace_and_verdict_graphflow_run_gives(pick_place):
    """Determinism: what the studio saves of a live run (made again from its input) is `graphflow run`'s trace, byte for byte."""
    from graphflow.verdicts.checked_run import run_checked

    path = pick_place.folder / "pick.json"
    with websockets_sync.connect(f"ws://127.0.0.1:{pick_place.port}/api/live?path=pick.json&token={pick_place.token}",
                                 open_timeout=30) as socket:
        until(socket, "start")
        step(socket, 7)
        socket.send(json.dumps({"command": "saveTrace", "path": "first7.jsonl"}))
        until(socket, "saved")
        socket.send(json.dumps({"command": "speed", "value": None}))
        socket.send(json.dumps({"command": "play"}))
        ended = until(socket, "frame", lambda message: message["ended"] is not None)["ended"]
        socket.send(json.dumps({"command": "saveTrace", "path": "live.jsonl"}))
        until(socket, "saved")
    verdict = run_checked(path, trace=pick_place.folder / "run.jsonl")
    headless = (pick_place.folder / "run.jsonl").read_text()
    assert (pick_place.folder / "live.jsonl").read_text() == headless
    assert (ended["passed"], ended["failures"]) == (verdict.run_passed, verdict.failures)
    assert ended["checks"] == verdict.checks == 6
    lines = headless.splitlines(keepends=True)
    assert (pick_place.folder / "first7.jsonl").read_text() == "".join(lines[:8])   # the header and ticks 1-7


def test_the_live_run_goes_on_while_a_save_replays_it(pick_place):
    """The replay runs in a process of its own: steps sent after a save are answered before the file is written."""
    from graphflow.verdicts.checked_run import run_checked

    with websockets_sync.connect(f"ws://127.0.0.1:{pick_place.port}/api/live?path=pick.json&token={pick_place.token}",
                                 open_timeout=30) as socket:
        until(socket, "start")
        step(socket, 5)
        socket.send(json.dumps({"command": "saveTrace", "path": "five.jsonl"}))
        for _ in range(3):
            socket.send(json.dumps({"command": "step"}))
        answered = []
        while (message := json.loads(socket.recv(timeout=120)))["type"] != "saved":
            assert message["type"] == "frame", message
            answered.append(message["tick"])
    assert answered and answered[-1] == 8   # every step answered (frames waiting merge) while the replay went on elsewhere
    run_checked(pick_place.folder / "pick.json", trace=pick_place.folder / "run.jsonl")
    lines = (pick_place.folder / "run.jsonl").read_text().splitlines(keepends=True)
    assert (pick_place.folder / "five.jsonl").read_text() == "".join(lines[:6])   # the header and ticks 1-5
