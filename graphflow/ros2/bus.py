"""The topic bus: one per world, the only thing ROS 2 bridge nodes talk to.

Publisher nodes call ``publish``; subscriber nodes ask ``latest(topic)`` and
compare its sequence number with the last one they used, so each message is
taken once per node, as a ROS 2 subscription with a queue of one would. The
bus is a world service: after every physics step it clears the previous
tick's published list and polls its transports for messages due by the
world's simulated time; ``world.reset()`` rewinds them, so a run replays
exactly.

Transports connect the bus to the outside. Headless, ``ScriptedTopics``
(``graphflow.ros2.timeline``) delivers a timeline and ``McapRecording``
(``graphflow.ros2.mcap_recording``) writes what is published. A live ROS 2
transport would implement the same four methods on rclpy (see docs/ros2.md).
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Iterable, Protocol, TypeVar

from graphflow.ros2.messages import complete
from graphflow.ros2.messages import type_name as standard_type


@dataclass(frozen=True)
class TopicMessage:
    """One message on the bus: topic, ROS 2 type (``pkg/msg/Name``, None when a timeline left it open),
    the message as a dict, the simulated time it was sent or delivered, and its bus sequence number."""

    topic: str
    type: str | None
    message: dict
    time: float
    sequence: int

    def to_json(self) -> dict:
        return {"topic": self.topic, "type": self.type, "message": self.message}


class Transport(Protocol):
    """Where messages come from and go to (scripted timeline, MCAP file, a live ROS 2 graph)."""

    def receive(self, time: float) -> list[tuple[str, str | None, dict]]:
        """Messages ``(topic, type or None, message)`` that arrived up to simulated *time*, in order."""

    def send(self, message: TopicMessage) -> None:
        """A message a node published."""

    def rewind(self) -> None:
        """The world was reset: replay from the start."""

    def close(self) -> None:
        """The run ended: flush and release what the transport holds."""


class TopicBus:
    """The topics of one world (a ``WorldService``): latest message per topic, this tick's publications."""

    def __init__(self, world, transports: Iterable[Transport] = ()):
        self.world = world
        self.transports: list[Transport] = list(transports)
        self.published: list[TopicMessage] = []   # published during the current tick, in order
        self._latest: dict[str, TopicMessage] = {}
        self._sequence = 0

    def add_transport(self, transport: Transport) -> Transport:
        self.transports.append(transport)
        return transport

    def publish(self, topic: str, type_name: str, message: dict) -> TopicMessage:
        """Check *message* against *type_name*, make it the topic's latest, hand it to every transport."""
        full_type = standard_type(type_name)
        sent = self._deliver(topic, full_type, complete(full_type, message, f"topic {topic}"))
        self.published.append(sent)
        for transport in self.transports:
            transport.send(sent)
        return sent

    def publish_service_part(self, topic: str, type_name: str, message: dict) -> TopicMessage:
        """A service request or response, already checked (``graphflow.ros2.services``): on the bus and in
        the trace, but not sent to transports, whose MCAP schemas come from message definitions only."""
        sent = self._deliver(topic, type_name, message)
        self.published.append(sent)
        return sent

    def latest(self, topic: str) -> TopicMessage | None:
        """The newest message on *topic* (published here or received), or None."""
        return self._latest.get(topic)

    def after_step(self, dt: float) -> None:
        self.published = []
        for transport in self.transports:
            for topic, type_name, message in transport.receive(self.world.time):
                self._deliver(topic, type_name, message)

    def reset(self) -> None:
        self.published = []
        self._latest.clear()
        self._sequence = 0
        for transport in self.transports:
            transport.rewind()

    def close(self) -> None:
        for transport in self.transports:
            transport.close()

    def _deliver(self, topic: str, type_name: str | None, message: dict) -> TopicMessage:
        self._sequence += 1
        delivered = TopicMessage(topic, type_name, message, self.world.time, self._sequence)
        self._latest[topic] = delivered
        return delivered


AnyTransport = TypeVar("AnyTransport", bound=Transport)


def attach_transport(world, transport: AnyTransport) -> AnyTransport:
    """Connect *transport* to the topic bus of *world*; the same transport is returned, its type kept."""
    topic_bus_for(world).add_transport(transport)
    return transport


def topic_bus_for(world) -> TopicBus:
    """The topic bus of *world*, made on first use (no transports: nothing arrives, publications stay in the run)."""
    return world.services.require(TopicBus, lambda: TopicBus(world))


def published_this_tick(world) -> list[dict]:
    """What nodes published during the tick that just ran, for the trace (empty when there is no bus)."""
    bus = world.services.get(TopicBus)
    return [message.to_json() for message in bus.published] if bus is not None else []
