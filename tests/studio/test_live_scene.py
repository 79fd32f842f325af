"""The scene and lanes part of the live frames (graphflow/studio/frame_scene.py), read over the websocket."""
import json
import shutil

import pytest

from graphflow.observe.trace import read_trace

from .conftest import GRAPHS, Studio

websockets_sync = pytest.importorskip("websockets.sync.client")

CUBE = "/World/Cube"
GRIPPER = "/World/ur10/ee_link/SurfaceGripper"
PHASE = "pick_place.eventName"
STEPS = 12   # ticks stepped one at a time after playing


@pytest.fixture
def pick_place(tmp_path):
    shutil.copy(GRAPHS / "ur10_pick_place.json", tmp_path / "pick.json")
    server = Studio(tmp_path, "pick.json")
    yield server
    server.stop()


def receive(socket, frames, last):
    """Add the frames received to *frames* until one is *last*."""
    while True:
        message = json.loads(socket.recv(timeout=120))
        assert message["type"] != "error", message
        if message["type"] == "frame":
            frames.append(message)
            if last(message):
                return


def frames_until(socket, tick):
    """Every frame of a run played at max speed until one reaches *tick*, then of STEPS single steps; the trace saved."""
    frames = []
    socket.send(json.dumps({"command": "speed", "value": None}))
    socket.send(json.dumps({"command": "play"}))
    receive(socket, frames, lambda frame: frame["tick"] >= tick)
    socket.send(json.dumps({"command": "pause"}))
    receive(socket, frames, lambda frame: not frame["playing"])
    paused = frames[-1]["tick"]
    for step in range(1, STEPS + 1):   # one frame a tick (each awaited: none merged), the cube carried now
        socket.send(json.dumps({"command": "step"}))
        receive(socket, frames, lambda frame: frame["tick"] == paused + step)
    socket.send(json.dumps({"command": "saveTrace", "path": "live.jsonl"}))
    while json.loads(socket.recv(timeout=120))["type"] != "saved":
        pass
    return frames


def test_the_frames_carry_every_phase_and_gripper_change_and_the_bodies_last_poses(pick_place):
    url = f"ws://127.0.0.1:{pick_place.port}/api/live?path=pick.json&token={pick_place.token}"
    with websockets_sync.connect(url, open_timeout=30) as socket:
        frames = frames_until(socket, 700)
    trace = read_trace(pick_place.folder / "live.jsonl")
    last = frames[-1]["tick"]
    assert len(frames) < last / 2   # frames merged several ticks each: what each carries is what those ticks did
    records = [record for record in trace.ticks if record["tick"] <= last]
    phases = [change for frame in frames for change in frame["lanes"]["phases"].get(PHASE, [])]
    assert phases == [[r["tick"], r["outputs"][PHASE]] for r in records if PHASE in r.get("outputs", {})]
    statuses = [change for frame in frames for change in frame["lanes"]["grippers"].get(GRIPPER, {}).get("status", [])]
    assert statuses == [[r["tick"], r["grippers"][GRIPPER]["status"]] for r in records
                        if "status" in r.get("grippers", {}).get(GRIPPER, {})]
    assert [value for _tick, value in statuses][-1] == "Closed" and len(phases) >= 4   # the run got to the carry
    samples = {r["tick"]: r["poses"][CUBE] for r in records if CUBE in r.get("poses", {})}
    compared = 0
    for frame in frames:   # the trace samples poses every 4th tick: on those ticks its last sample is the pose then
        sent = frame["scene"]["poses"].get(CUBE)
        if sent is not None and sent[0] % 4 == 0:
            assert sent[0] == frame["tick"]
            assert sent[1] == pytest.approx(samples[max(tick for tick in samples if tick <= sent[0])], abs=1e-5)
            compared += 1
    assert compared >= STEPS // 4, compared
    closes = [close for frame in frames for close in frame["scene"]["rays"]]   # each close's rays, cast on its tick
    assert closes == [{"tick": r["tick"], "gripper": path, "rays": close["rays"]}
                      for r in records for path, close in sorted(r.get("rays", {}).items())]
    assert closes and closes[-1]["rays"][0]["hit"]["prim"] == CUBE   # the close that picked the cube saw it
    limits = [frame["scene"]["limits"][GRIPPER] for frame in frames if GRIPPER in frame["scene"]["limits"]]
    assert limits == [next(close["limits"] for r in records for close in r.get("rays", {}).values())]   # sent once


def test_two_frames_merged_keep_every_lane_change_and_the_newest_poses():
    from graphflow.studio.frame_scene import merge_parts

    older = {"scene": {"poses": {"/a": [4, [1.0] * 7], "/b": [4, [2.0] * 7]}, "limits": {"/g": {"shear": 500.0}},
                       "rays": [{"tick": 4, "gripper": "/g", "rays": []}]},
             "lanes": {"phases": {"c.eventName": [[3, "descend"]]}, "grippers": {"/g": {"status": [[4, "Closing"]]}}}}
    newer = {"scene": {"poses": {"/a": [8, [3.0] * 7]}, "limits": {}, "rays": [{"tick": 9, "gripper": "/g", "rays": []}]},
             "lanes": {"phases": {"c.eventName": [[7, "lift"]]}, "grippers": {"/g": {"status": [[5, "Closed"]]}}}}
    merged = merge_parts(older, newer)
    assert merged["scene"] == {"poses": {"/a": [8, [3.0] * 7], "/b": [4, [2.0] * 7]}, "limits": {"/g": {"shear": 500.0}},
                               "rays": [{"tick": 4, "gripper": "/g", "rays": []}, {"tick": 9, "gripper": "/g", "rays": []}]}
    assert merged["lanes"] == {"phases": {"c.eventName": [[3, "descend"], [7, "lift"]]},
                               "grippers": {"/g": {"status": [[4, "Closing"], [5, "Closed"]]}}}
    assert older["lanes"]["phases"]["c.eventName"] == [[3, "descend"]]   # the frames themselves left as they were
