"""What the keyboard and the gamepad share: one device per world, a service the world owns.

Every node of every graph instance asks the device for the current step's
snapshot, so they all see the same events in the same tick, whoever asks first.
The source is polled on the first request of a physics step (scripted sources
return everything due by then, so nothing is missed when no node asks for a
while). The world resets the device with itself: it forgets its state and
rewinds a scripted source, so the run replays exactly.
"""
from __future__ import annotations

from typing import Generic, TypeVar

Snapshot = TypeVar("Snapshot")


class StepPolledDevice(Generic[Snapshot]):
    """Base of an input device (a ``WorldService``): subclasses say how a poll's changes update their state."""

    def __init__(self, source, world):
        self.source = source
        self.world = world
        self._step = -1
        self._snapshot: Snapshot = self._advance(-1, ())

    def snapshot(self) -> Snapshot:
        """The state after the current physics step's changes (polled on the first call of the step)."""
        step = self.world.step_index
        if step != self._step:
            self._snapshot = self._advance(step, tuple(self.source.poll(self.world.time)))
            self._step = step
        return self._snapshot

    def after_step(self, dt: float) -> None:
        """Nothing to do per step: the source is polled when a node first asks."""

    def reset(self) -> None:
        self._forget()
        rewind = getattr(self.source, "rewind", None)
        if rewind is not None:
            rewind()
        self._step = -1
        self._snapshot = self._advance(-1, ())

    def _advance(self, step: int, changes: tuple) -> Snapshot:
        """Apply one poll's changes, in order, and return the step's snapshot."""
        raise NotImplementedError

    def _forget(self) -> None:
        """Drop the remembered state (the world was reset)."""
        raise NotImplementedError


def timeline_entries(path, section: str, required: tuple[str, ...], optional: tuple[str, ...], error: type,
                     example: str) -> list[tuple[str, dict]]:
    """The entries of a scripted-input file ``{section: [{...}, ...]}`` with where each stands, for the caller to read.

    Strict JSON, regular files only; a missing or unknown key is one ``error`` line naming the file and
    the entry (the gamepad's and the ROS 2 topics' timelines share this shape).
    """
    from graphflow.files import FileProblem, read_json

    try:
        data = read_json(path)
    except FileProblem as problem:
        raise error(str(problem)) from None
    entries = data.get(section) if isinstance(data, dict) else None
    if not isinstance(entries, list) or not all(isinstance(entry, dict) for entry in entries):
        raise error(f"{path}: expected an object with a '{section}' list of {example} entries")
    result = []
    for index, entry in enumerate(entries):
        where = f"{path}: {section}[{index}]"
        missing = sorted(set(required) - set(entry))
        unknown = sorted(set(entry) - set(required) - set(optional))
        if missing:
            raise error(f"{where}: missing {', '.join(missing)}")
        if unknown:
            raise error(f"{where}: unknown {', '.join(unknown)} (an entry has {', '.join(required + optional)})")
        result.append((where, entry))
    return result
