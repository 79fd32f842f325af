"""The ROS 2 side of ``graphflow run``: scripted topics in, an MCAP recording out."""
from __future__ import annotations

from graphflow.ros2.bus import attach_transport
from graphflow.ros2.mcap_recording import (
    McapRecording,
    RecordingError,
    check_recording_path,
)
from graphflow.ros2.timeline import TopicSpecError, scripted_topics

__all__ = ["RunOptionError", "check_options", "attach_topics"]

RunOptionError = (TopicSpecError, RecordingError)


def check_options(topics_file, topic_specs, record_path):
    """The scripted topics (None without --topics/--topic), after checking the recording path; raises RunOptionError."""
    if record_path:
        check_recording_path(record_path)
    return scripted_topics(topics_file, topic_specs)


def attach_topics(world, topics, record_path) -> McapRecording | None:
    """Connect the scripted topics and the MCAP recording (if any) to *world*'s topic bus; the recording is returned
    so the caller closes it when the run ends."""
    if topics is not None:
        attach_transport(world, topics)
    return attach_transport(world, McapRecording(record_path)) if record_path else None
