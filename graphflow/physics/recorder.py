"""Video of a run: frames from PyBullet's TinyRenderer (works headless, no GPU), written as GIF, MP4 or PNGs.

``graphflow run GRAPH --record run.gif`` captures one frame every k-th tick so
the video plays at the requested rate in simulated time (k = round(1 / (fps *
time step)); the file's frame rate is then exactly 1 / (k * time step)). GIFs
are written with Pillow; MP4 needs an encoder (the ``imageio-ffmpeg`` package
or an ``ffmpeg`` program on PATH); a folder gets one PNG per frame, named by tick.
"""
from __future__ import annotations

import functools
import math
import shutil
import subprocess
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Generator

import numpy as np
import pybullet

from graphflow.errors import BadInput

if TYPE_CHECKING:
    from PIL import Image

FIELD_OF_VIEW = 50.0            # degrees, vertical
NEAR, FAR = 0.01, 100.0         # m, clipping planes
LARGEST_FRAMED_BODY = 20.0      # m: bigger bodies (ground planes) are left out when framing the scene
LIGHT_DIRECTION = (0.6, 0.3, 1.0)
BACKGROUND_TOP = np.array([0.80, 0.86, 0.92], dtype=np.float32) * 255.0
BACKGROUND_BOTTOM = np.array([0.95, 0.96, 0.97], dtype=np.float32) * 255.0
GROUND = (0.86, 0.87, 0.88)
PALETTE = ((0.55, 0.60, 0.68), (0.95, 0.55, 0.20), (0.30, 0.62, 0.40), (0.85, 0.30, 0.30), (0.55, 0.40, 0.75))


class RecordingError(BadInput):
    """The recording cannot be made as asked (unknown format, no encoder, bad size): bad input, exit 2."""


@dataclass(frozen=True)
class Camera:
    """Orbit camera (PyBullet's convention: yaw and pitch in degrees, z up). None = frame the whole scene."""

    target: tuple[float, float, float] | None = None
    distance: float | None = None
    yaw: float = 50.0
    pitch: float = -30.0


def video_kind(path: str | Path) -> str:
    """``gif``, ``mp4`` or ``frames`` (a folder: a path ending in a separator, an existing folder or no suffix)."""
    text = str(path)
    target = Path(text)
    if text.endswith(("/", "\\")) or target.is_dir() or not target.suffix:
        return "frames"
    suffix = target.suffix.lower()
    if suffix in (".gif", ".mp4"):
        return suffix[1:]
    raise RecordingError(f"{path}: cannot record to {suffix} files; use .gif, .mp4 or a folder for PNG frames")


def check_encoder(path: str | Path) -> None:
    """Fail before the run, not after it, when an MP4 cannot be encoded here."""
    if video_kind(path) == "mp4" and _imageio_ffmpeg() is None and shutil.which("ffmpeg") is None:
        raise RecordingError(f"{path}: no MP4 encoder found (pip install imageio-ffmpeg, or install ffmpeg); "
                             f"--record run.gif needs none")


def _imageio_ffmpeg():
    try:
        import imageio_ffmpeg
    except ImportError:
        return None
    return imageio_ffmpeg


def gif_frame_durations(count: int, fps: float) -> list[int]:
    """Per-frame display times (ms) for a GIF at *fps*.

    GIF stores frame times in whole centiseconds, so 15 fps (66.7 ms) cannot be one
    value; each frame ends at the centisecond nearest its true end time instead
    (70, 70, 60, ...), so the video keeps time with the simulation.
    """
    ends = [round((index + 1) * 100.0 / fps) for index in range(count)]
    return [10 * max(1, end - start) for start, end in zip([0] + ends[:-1], ends)]


class _ClientCalls:
    """PyBullet calls bound to one client id (worlds may hand out a bare id instead of a BulletClient)."""

    def __init__(self, client_id: int):
        self._client_id = client_id

    def __getattr__(self, name):
        return functools.partial(getattr(pybullet, name), physicsClientId=self._client_id)


def bullet_calls(client):
    """An object with PyBullet's functions for this client: the BulletClient itself, or calls bound to the id."""
    return _ClientCalls(client) if isinstance(client, int) else client


def scene_bounds(client) -> tuple[np.ndarray, np.ndarray] | None:
    """Axis-aligned bounds of every body and link smaller than LARGEST_FRAMED_BODY, or None for an empty scene."""
    bullet = bullet_calls(client)
    lows, highs = [], []
    for index in range(bullet.getNumBodies()):
        body = bullet.getBodyUniqueId(index)
        for link in range(-1, bullet.getNumJoints(body)):
            low, high = (np.asarray(corner, dtype=float) for corner in bullet.getAABB(body, link))
            if np.all(high >= low) and np.max(high - low) <= LARGEST_FRAMED_BODY:
                lows.append(low)
                highs.append(high)
    if not lows:
        return None
    return np.min(lows, axis=0), np.max(highs, axis=0)


def framed_camera(client, camera: Camera) -> Camera:
    """Fill in a missing target or distance so the whole scene is in view."""
    if camera.target is not None and camera.distance is not None:
        return camera
    bounds = scene_bounds(client)
    low, high = bounds if bounds is not None else (np.full(3, -0.5), np.full(3, 0.5))
    radius = max(0.25, float(np.linalg.norm(high - low)) / 2)
    centre = (low + high) / 2
    target = camera.target if camera.target is not None else (float(centre[0]), float(centre[1]), float(centre[2]))
    distance = camera.distance if camera.distance is not None else 1.15 * radius / math.sin(math.radians(FIELD_OF_VIEW / 2))
    return Camera(target, distance, camera.yaw, camera.pitch)


def render_frame(client, size: tuple[int, int], camera: Camera, colours: dict[int, tuple] | None = None) -> np.ndarray:
    """One RGB frame (height x width x 3, uint8) from the TinyRenderer; *camera* must be framed.

    The background becomes a soft gradient and every body is tinted (``colours``
    by body id, see ``body_colours``), keeping the renderer's shading, so the
    uncoloured PyBullet shapes read apart from each other and from the sky.
    """
    width, height = size
    bullet = bullet_calls(client)
    view = bullet.computeViewMatrixFromYawPitchRoll(cameraTargetPosition=camera.target, distance=camera.distance,
                                                    yaw=camera.yaw, pitch=camera.pitch, roll=0.0, upAxisIndex=2)
    projection = bullet.computeProjectionMatrixFOV(fov=FIELD_OF_VIEW, aspect=width / height, nearVal=NEAR, farVal=FAR)
    _, _, rgba, _, segmentation = bullet.getCameraImage(width, height, viewMatrix=view, projectionMatrix=projection,
                                                        renderer=pybullet.ER_TINY_RENDERER,
                                                        lightDirection=LIGHT_DIRECTION, shadow=1)
    shade = np.asarray(rgba, dtype=np.float32).reshape(height, width, 4)[:, :, :3] / 255.0
    bodies = np.asarray(segmentation, dtype=np.int64).reshape(height, width)
    rows = np.linspace(0.0, 1.0, height, dtype=np.float32)[:, None, None]
    image = (1.0 - rows) * BACKGROUND_TOP + rows * BACKGROUND_BOTTOM + np.zeros((1, width, 3), np.float32)
    for body in np.unique(bodies[bodies >= 0]):
        mask = bodies == body
        colour = np.asarray((colours or {}).get(int(body), PALETTE[0]), dtype=np.float32)
        image[mask] = shade[mask] * colour * 255.0
    return np.clip(image, 0, 255).astype(np.uint8)


def body_colours(world) -> dict[int, tuple[float, float, float]]:
    """Body id -> tint (0..1 RGB): the USD ``primvars:displayColor`` on or below the body's prim, grey for
    ground-sized bodies, else a palette colour."""
    bullet = bullet_calls(world.client)
    stage = getattr(world, "stage", None)
    prims = {body: path for (body, link), path in getattr(getattr(world, "scene", None), "by_id", {}).items() if link == -1}
    colours = {}
    for index in range(bullet.getNumBodies()):
        body = bullet.getBodyUniqueId(index)
        authored = _display_colour(stage.GetPrimAtPath(prims[body])) if stage is not None and body in prims else None
        low, high = (np.asarray(corner, dtype=float) for corner in bullet.getAABB(body, -1))
        if authored is not None:
            colours[body] = authored
        elif np.max(high - low) > LARGEST_FRAMED_BODY:
            colours[body] = GROUND
        else:
            colours[body] = PALETTE[len(colours) % len(PALETTE)]
    return colours


def _display_colour(prim):
    pending = [prim]
    while pending:
        current = pending.pop(0)
        if not current.IsValid():
            continue
        value = current.GetAttribute("primvars:displayColor").Get() if current.HasAttribute("primvars:displayColor") else None
        if value:
            return tuple(float(c) for c in value[0])
        pending.extend(current.GetChildren())
    return None


class VideoRecorder:
    """Captures the world every k-th tick and writes the video when closed.

    A world service: create it before the run (it captures the initial state as
    the first frame), add it with ``world.services.add(recorder)`` so every
    physics step captures (``after_step``), and ``close()`` it at the end. After
    a world reset the restored initial state is the next frame.
    """

    def __init__(self, world, path: str | Path, *, fps: float = 30.0, size: tuple[int, int] = (480, 360),
                 camera: Camera = Camera(), write_to: str | Path | None = None):
        """*path* names the video (its kind comes from it); files go to *write_to* if given (a temporary
        file or folder the caller renames into place once the video is complete)."""
        if size[0] < 16 or size[1] < 16:
            raise RecordingError(f"video size {size[0]}x{size[1]} is too small (at least 16x16)")
        if not fps > 0:
            raise RecordingError(f"frames per second must be positive, got {fps}")
        check_encoder(path)
        self.world = world
        self.kind = video_kind(path)
        self.path = Path(write_to if write_to is not None else path)
        self.size = size
        self.ticks_per_frame = max(1, round(1.0 / (fps * world.time_step)))
        self.fps = 1.0 / (self.ticks_per_frame * world.time_step)
        self.camera = framed_camera(world.client, camera)
        self.colours = body_colours(world)
        self.frame_count = 0
        self._gif_frames: list[Image.Image] = []
        self._encoder: subprocess.Popen[bytes] | Generator[None, bytes | None, None] | None = None
        self._write(render_frame(world.client, size, self.camera, self.colours))

    def capture(self) -> None:
        """Take a frame if this tick is on the frame grid."""
        if self.world.step_index % self.ticks_per_frame == 0:
            self._write(render_frame(self.world.client, self.size, self.camera, self.colours))

    def after_step(self, _dt: float) -> None:
        self.capture()

    def reset(self) -> None:
        self.capture()

    def _write(self, frame: np.ndarray) -> None:
        from PIL import Image

        self.frame_count += 1
        if self.kind == "gif":
            self._gif_frames.append(Image.fromarray(frame).quantize(colors=256, method=Image.Quantize.MEDIANCUT))
        elif self.kind == "frames":
            self.path.mkdir(parents=True, exist_ok=True)
            Image.fromarray(frame).save(self.path / f"tick_{self.world.step_index:06d}.png")
        else:
            encoder = self._mp4_encoder()
            if isinstance(encoder, subprocess.Popen):
                assert encoder.stdin is not None     # started with stdin=PIPE
                encoder.stdin.write(frame.tobytes())
            else:
                encoder.send(frame.tobytes())

    def _mp4_encoder(self):
        if self._encoder is None:
            width, height = self.size
            imageio_ffmpeg = _imageio_ffmpeg()
            if imageio_ffmpeg is not None:
                self._encoder = imageio_ffmpeg.write_frames(str(self.path), (width, height), fps=self.fps,
                                                            macro_block_size=2, quality=7)
                self._encoder.send(None)
            else:
                self._encoder = subprocess.Popen(
                    ["ffmpeg", "-loglevel", "error", "-y", "-f", "rawvideo", "-pix_fmt", "rgb24",
                     "-s", f"{width}x{height}", "-r", repr(self.fps), "-i", "-",
                     "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-pix_fmt", "yuv420p", str(self.path)],
                    stdin=subprocess.PIPE)
        return self._encoder

    def close(self) -> None:
        """Finish the file (GIF frames are written here; the MP4 encoder is flushed)."""
        if self.kind == "gif" and self._gif_frames:
            first, *rest = self._gif_frames
            first.save(self.path, format="GIF", save_all=True, append_images=rest,
                       duration=gif_frame_durations(len(self._gif_frames), self.fps), loop=0)
            self._gif_frames = []
        elif self._encoder is not None:
            if isinstance(self._encoder, subprocess.Popen):
                assert self._encoder.stdin is not None     # started with stdin=PIPE
                self._encoder.stdin.close()
                if self._encoder.wait() != 0:
                    raise RecordingError(f"{self.path}: ffmpeg failed to encode the video")
            else:
                self._encoder.close()
            self._encoder = None
