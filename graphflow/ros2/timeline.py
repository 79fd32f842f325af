"""Scripted topics for headless runs: ``graphflow run --topics FILE --topic SPEC``.

A file is ``{"topics": [{"topic": "/joint_command", "time": 0.5,
"type": "sensor_msgs/msg/JointState", "message": {...}}, ...]}`` (``type``
optional: the subscribing node checks the message against its own type). A
flag is ``TOPIC@TIME=JSON``, e.g. ``/cmd_vel@1.0={"linear": {"x": 0.5}}``.
Entries are delivered after the first physics step whose simulated time
reaches theirs, in time order (file order, then flag order, for equal times).
"""
from __future__ import annotations

import math
import re
from dataclasses import dataclass
from pathlib import Path
from typing import Iterable

from graphflow.errors import BadInput
from graphflow.files import FileProblem, loads_strict
from graphflow.inputs.device import timeline_entries
from graphflow.ros2.messages import MessageError, complete, type_name


class TopicSpecError(BadInput):
    """A timeline entry that cannot be read; the message quotes it."""


@dataclass(frozen=True)
class ScriptedMessage:
    topic: str
    time: float
    message: dict
    type: str | None = None


class ScriptedTopics:
    """A timeline of incoming messages (a bus ``Transport``); publications are not its business."""

    def __init__(self, entries: Iterable[ScriptedMessage]):
        indexed = sorted(enumerate(entries), key=lambda pair: (pair[1].time, pair[0]))
        self.entries = tuple(entry for _, entry in indexed)
        self._next = 0

    def receive(self, time: float) -> list[tuple[str, str | None, dict]]:
        due = []
        while self._next < len(self.entries) and self.entries[self._next].time <= time + 1e-9:
            entry = self.entries[self._next]
            due.append((entry.topic, entry.type, entry.message))
            self._next += 1
        return due

    def send(self, message) -> None:
        """Published messages are recorded elsewhere (trace, MCAP)."""

    def rewind(self) -> None:
        self._next = 0

    def close(self) -> None:
        """Nothing held."""


def make_entry(topic, time, message, type_=None, *, where: str) -> ScriptedMessage:
    """A checked entry; *where* names it in error messages."""
    if not isinstance(topic, str) or not re.fullmatch(r"/?[A-Za-z_~{][A-Za-z0-9_/{}~]*", topic):
        raise TopicSpecError(f"{where}: topic must be a ROS 2 name such as /joint_command, got {topic!r}")
    if isinstance(time, bool) or not isinstance(time, (int, float)) or not math.isfinite(time) or time < 0:
        raise TopicSpecError(f"{where}: time must be a number of seconds >= 0, got {time!r}")
    if not isinstance(message, dict):
        raise TopicSpecError(f"{where}: message must be a JSON object of message fields, got {message!r}")
    try:
        if type_ is not None:
            type_ = type_name(type_)
            message = complete(type_, message, "message")
    except MessageError as error:
        raise TopicSpecError(f"{where}: {error}") from None
    return ScriptedMessage(topic if topic.startswith("/") else "/" + topic, float(time), message, type_)


_SPEC = re.compile(r"^(?P<topic>[^@=]+)@(?P<time>[0-9]*\.?[0-9]+(?:[eE][+-]?[0-9]+)?)=(?P<json>.*)$", re.S)


def parse_topic_spec(text: str) -> ScriptedMessage:
    """``/joint_command@0.5={"name": ["j1"], "position": [0.3]}``: TOPIC@TIME=JSON message."""
    match = _SPEC.match(text.strip())
    if not match:
        raise TopicSpecError(f"topic {text!r}: expected TOPIC@TIME=JSON, e.g. '/cmd_vel@1.0={{\"linear\": {{\"x\": 0.5}}}}'")
    try:
        message = loads_strict(match["json"], f"topic {text!r}")
    except FileProblem as error:
        raise TopicSpecError(f"topic {text!r}: the message is not JSON ({error.reason})") from None
    return make_entry(match["topic"].strip(), float(match["time"]), message, where=f"topic {text!r}")


def load_topic_timeline(path: str | Path) -> list[ScriptedMessage]:
    """Read a topics file (see the module docstring)."""
    entries = timeline_entries(path, "topics", ("topic", "time", "message"), ("type",), TopicSpecError,
                               '{"topic": ..., "time": ..., "message": {...}}')
    return [make_entry(entry["topic"], entry["time"], entry["message"], entry.get("type"), where=where)
            for where, entry in entries]


def scripted_topics(path: str | Path | None, specs: Iterable[str] = ()) -> ScriptedTopics | None:
    """The timeline of ``graphflow run --topics FILE --topic SPEC ...`` (file first), or None if neither is given."""
    entries = load_topic_timeline(path) if path is not None else []
    entries.extend(parse_topic_spec(spec) for spec in specs)
    if path is None and not entries:
        return None
    return ScriptedTopics(entries)
