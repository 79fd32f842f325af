"""Kit's application events headless: what Send*Event nodes push, On*Event nodes receive the next tick.

Not a node type. Kit delivers custom and message-bus events asynchronously, on
a later update; here an event sent during a tick is delivered after the
world's step, so listeners fire on the next tick, in every graph of the world.
"""
from __future__ import annotations

CUSTOM, MESSAGE_BUS = "custom event", "message bus"


class AppEvents:
    """The events of one world (a ``WorldService``): those sent this tick, those delivered to this tick."""

    def __init__(self):
        self._sent: list[tuple[str, str, dict]] = []
        self._delivered: list[tuple[str, str, dict]] = []

    def send(self, channel: str, name: str, payload: dict) -> None:
        self._sent.append((channel, name, payload))

    def received(self, channel: str, name: str) -> list[dict]:
        """Payloads of the events named *name* delivered to this tick, in the order they were sent."""
        return [payload for sent_channel, sent_name, payload in self._delivered
                if sent_channel == channel and sent_name == name]

    def after_step(self, dt: float) -> None:
        self._delivered, self._sent = self._sent, []

    def reset(self) -> None:
        self._sent, self._delivered = [], []


def app_events(db) -> AppEvents:
    return db.world.services.require(AppEvents, AppEvents)
