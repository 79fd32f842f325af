"""Published messages to an MCAP file, ROS 2 profile, CDR encoding (``graphflow run --record-topics``).

``mcap-ros2-support`` encodes the dict messages to CDR from the definitions
rosbags supplies; the result opens in Foxglove and with ``ros2 bag`` (MCAP
storage). Log and publish times are the simulated time in nanoseconds, so
the same run writes the same messages. The file is written beside the target
and renamed into place when the run ends: an interrupted run leaves no
half-written recording.
"""
from __future__ import annotations

import os
from pathlib import Path
from typing import TYPE_CHECKING

from graphflow.errors import EXTRAS, BadInput, MissingExtra, require_extra
from graphflow.ros2.messages import definition

if TYPE_CHECKING:
    from mcap.records import Schema


class RecordingError(BadInput):
    """The recording cannot be made (file exists, folder missing, library missing)."""


def check_recording_path(path: str | Path) -> Path:
    """*path* as a Path when a recording may be written there; RecordingError (one line) when not."""
    require_extra("--record-topics", "ros", "mcap", "mcap_ros2")
    path = Path(path)
    if path.exists():
        raise RecordingError(f"{path}: already exists; not overwriting it")
    if not path.parent.is_dir():
        raise RecordingError(f"{path}: folder {path.parent} does not exist")
    return path


class McapRecording:
    """A bus ``Transport`` that writes every published message; receives nothing."""

    def __init__(self, path: str | Path):
        self.path = check_recording_path(path)
        try:
            from mcap.writer import CompressionType
            from mcap_ros2.writer import Writer
        except ImportError:
            raise MissingExtra("--record-topics", "ros", EXTRAS["ros"]) from None
        self._partial = self.path.with_name(self.path.name + ".partial")
        self._stream = open(self._partial, "wb")
        self._writer = Writer(self._stream, compression=CompressionType.NONE)
        self._schemas: dict[str, Schema] = {}

    def receive(self, time: float) -> list:
        return []

    def send(self, message) -> None:
        schema = self._schemas.get(message.type)
        if schema is None:   # published messages always carry a checked standard type
            schema = self._schemas[message.type] = self._writer.register_msgdef(message.type, definition(message.type))
        nanoseconds = round(message.time * 1e9)
        self._writer.write_message(message.topic, schema, message.message, log_time=nanoseconds,
                                   publish_time=nanoseconds, sequence=message.sequence)

    def rewind(self) -> None:
        """A reset world publishes again; the recording keeps what was sent before (times restart)."""

    def close(self) -> None:
        if self._stream.closed:
            return
        self._writer.finish()
        self._stream.close()
        os.replace(self._partial, self.path)

    def abandon(self) -> None:
        """Drop the partial file (the run could not start)."""
        if not self._stream.closed:
            self._stream.close()
        self._partial.unlink(missing_ok=True)
