"""Video frames from PyBullet's TinyRenderer show the robot; --record writes GIFs and PNG frames headless."""
import json
import subprocess
import sys

import numpy as np
import pytest

from graphflow import physics
from graphflow.physics.recorder import (
    BACKGROUND_BOTTOM,
    BACKGROUND_TOP,
    Camera,
    RecordingError,
    VideoRecorder,
    body_colours,
    check_encoder,
    framed_camera,
    render_frame,
)

SIZE = (64, 48)


@pytest.fixture
def ur10_world():
    world = physics.create_world("asset:ur10.usda")
    yield world
    world.close()


def background(height: int) -> np.ndarray:
    rows = np.linspace(0.0, 1.0, height)[:, None]
    return ((1 - rows) * BACKGROUND_TOP + rows * BACKGROUND_BOTTOM).astype(np.uint8)


def robot_pixels(frame: np.ndarray) -> np.ndarray:
    """True where the frame is not the background gradient."""
    return np.abs(frame.astype(int) - background(frame.shape[0])[:, None, :].astype(int)).max(axis=2) > 3


def test_a_frame_shows_the_robot_where_it_stands(ur10_world):
    camera = Camera(target=(0.0, 0.0, 0.4), distance=2.0, yaw=50.0, pitch=-20.0)
    frame = render_frame(ur10_world.client, SIZE, camera, body_colours(ur10_world))
    assert frame.shape == (48, 64, 3) and frame.dtype == np.uint8
    robot = robot_pixels(frame)
    assert robot[12:40, 24:40].mean() > 0.15          # the arm, around the image centre
    assert not robot[:6, :6].any() and not robot[:6, -6:].any()   # sky in the top corners
    looking_away = render_frame(ur10_world.client, SIZE, Camera(target=(0.0, 0.0, 5.0), distance=2.0, pitch=30.0))
    assert not robot_pixels(looking_away).any()


def test_the_default_camera_frames_the_whole_robot(ur10_world):
    camera = framed_camera(ur10_world.client, Camera())
    robot = robot_pixels(render_frame(ur10_world.client, SIZE, camera))
    assert robot.any()
    assert not (robot[0].any() or robot[-1].any() or robot[:, 0].any() or robot[:, -1].any())   # nothing cut off


def test_frames_are_taken_every_kth_tick_by_the_world_service(ur10_world, tmp_path):
    pytest.importorskip("PIL")
    recorder = ur10_world.services.add(VideoRecorder(ur10_world, tmp_path / "frames", fps=20.0, size=SIZE))
    assert recorder.ticks_per_frame == 3 and recorder.fps == pytest.approx(20.0)
    for _ in range(9):
        ur10_world.step()
    assert recorder.frame_count == 4
    ur10_world.reset()                                   # the restored initial state is the next frame
    assert recorder.frame_count == 5
    recorder.close()
    assert sorted(p.name for p in (tmp_path / "frames").iterdir()) == [
        "tick_000000.png", "tick_000003.png", "tick_000006.png", "tick_000009.png"]


def test_unknown_formats_and_missing_encoders_are_refused_up_front(tmp_path, monkeypatch):
    with pytest.raises(RecordingError, match="use .gif, .mp4 or a folder"):
        check_encoder(tmp_path / "run.avi")
    monkeypatch.setattr("graphflow.physics.recorder._imageio_ffmpeg", lambda: None)
    monkeypatch.setattr("shutil.which", lambda _name: None)
    with pytest.raises(RecordingError, match="no MP4 encoder found"):
        check_encoder(tmp_path / "run.mp4")


def graphflow(*args, cwd):
    return subprocess.run([sys.executable, "-m", "graphflow", *args], capture_output=True, text=True, cwd=cwd)


def test_run_record_writes_a_gif_at_the_requested_size(tmp_path):
    Image = pytest.importorskip("PIL.Image")

    graph = tmp_path / "idle.json"
    graph.write_text(json.dumps({"format": "graphflow", "formatVersion": [1, 0],
                                 "settings": {"stage": "asset:ur10.usda", "duration": 0.5},
                                 "nodes": [{"name": "tick", "type": "omni.graph.action.OnTick"}]}))
    result = graphflow("run", str(graph), "--record", "idle.gif", "--size", "64x48", "--fps", "10",
                       "--camera-target", "0,0,0.4", "--camera-distance", "2", cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    with Image.open(tmp_path / "idle.gif") as gif:
        assert gif.format == "GIF" and gif.size == SIZE
        assert robot_pixels(np.asarray(gif.convert("RGB"))).any()


def test_record_without_a_stage_or_with_a_bad_size_is_bad_input(tmp_path):
    core = tmp_path / "core.json"
    core.write_text(json.dumps({"format": "graphflow", "formatVersion": [1, 0],
                                "nodes": [{"name": "tick", "type": "omni.graph.action.OnTick"}]}))
    result = graphflow("run", str(core), "--record", "run.gif", cwd=tmp_path)
    assert result.returncode == 2 and "needs a graph with a stage" in result.stderr
    result = graphflow("run", str(core), "--record", "run.gif", "--size", "8x8", cwd=tmp_path)
    assert result.returncode == 2 and "WIDTHxHEIGHT" in result.stderr
