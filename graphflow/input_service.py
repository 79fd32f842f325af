"""What the keyboard and the gamepad share: one device per world, polled once per physics step.

Every node of every graph instance asks the device for the current step's
snapshot, so they all see the same events in the same tick, whoever asks first.
A world whose step index went back was reset: the device forgets its state and
rewinds a scripted source so the run replays exactly.
"""
from __future__ import annotations

import weakref
from typing import Callable, Generic, TypeVar

Snapshot = TypeVar("Snapshot")
Device = TypeVar("Device", bound="StepPolledDevice")


class StepPolledDevice(Generic[Snapshot]):
    """Base of an input device: subclasses say how a poll's changes update their state."""

    def __init__(self, source):
        self.source = source
        self._step = -1
        self._snapshot: Snapshot = self._advance(-1, ())

    def snapshot(self, world) -> Snapshot:
        """The state after the current physics step's changes (polled on the first call of the step)."""
        step = world.step_index
        if step != self._step:
            if step < self._step:
                self._forget()
                rewind = getattr(self.source, "rewind", None)
                if rewind is not None:
                    rewind()
            self._snapshot = self._advance(step, tuple(self.source.poll(world.time)))
            self._step = step
        return self._snapshot

    def _advance(self, step: int, changes: tuple) -> Snapshot:
        """Apply one poll's changes, in order, and return the step's snapshot."""
        raise NotImplementedError

    def _forget(self) -> None:
        """Drop the remembered state (the world was reset)."""
        raise NotImplementedError


class PerWorld(Generic[Device]):
    """The device attached to each world (weakly held: a closed world takes its device with it)."""

    def __init__(self, make_default: Callable[[object], Device]):
        self._devices: "weakref.WeakKeyDictionary[object, Device]" = weakref.WeakKeyDictionary()
        self._make_default = make_default

    def attach(self, world, device: Device) -> Device:
        self._devices[world] = device
        return device

    def get(self, world) -> Device:
        device = self._devices.get(world)
        if device is None:
            device = self.attach(world, self._make_default(world))
        return device
