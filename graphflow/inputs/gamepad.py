"""Gamepad input for graphs: one pad-state service per world, fed by a pluggable source.

``OnGamepadInput`` and ``ReadGamepadState`` nodes never talk to a device. They
ask ``gamepad_for(db.world)`` for the tick's ``PadSnapshot``: the ordered
element changes since the previous physics step and every element's value
now. The ``Gamepad`` polls its source at most once per physics step (keyed on
``world.step_index``), so every node of every graph instance sees the same
values in the same tick, whoever asks first. Nothing reads the wall clock.

Elements are Kit's gamepad tokens as OmniGraph's nodes name them (the
``allowedTokens`` of ``ReadGamepadState.inputs:gamepadElement`` in Isaac's
gantry file, in that order): four stick axes in [-1, 1], two triggers in
[0, 1] and fourteen buttons in [0, 1]. A scripted value is what the nodes
read; which way a physical stick moves for a positive Y is Kit's business and
not modelled here. A button is pressed while its value is at least 0.5.

Sources (all return ordered ``(pad, element, value)`` changes for a poll at a
simulated time):

* ``ScriptedPad`` - a timeline for headless runs and tests
  (``graphflow run --gamepad FILE`` / ``--pad "Left Stick X Axis=0.5@1.0"``);
* nothing attached: one neutral pad (id 0, every element 0). A real gamepad
  is not read, not even in the PyBullet window.

Pads are numbered from 0 as Kit's ``gamepadId``. Pad 0 is always connected;
a scripted timeline connects every pad it names.
"""
from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path
from typing import Iterable, Mapping, Protocol

from graphflow.errors import BadInput
from graphflow.inputs.device import StepPolledDevice, timeline_entries

STICK_AXES = ("Left Stick X Axis", "Left Stick Y Axis", "Right Stick X Axis", "Right Stick Y Axis")
TRIGGERS = ("Left Trigger", "Right Trigger")
# OnGamepadInput's allowedTokens: the elements with a press and a release
BUTTONS = (
    "Face Button Bottom", "Face Button Right", "Face Button Left", "Face Button Top",
    "Left Shoulder", "Right Shoulder", "Special Left", "Special Right",
    "Left Stick Button", "Right Stick Button", "D-Pad Up", "D-Pad Right", "D-Pad Down", "D-Pad Left",
)
ELEMENTS = STICK_AXES + TRIGGERS + BUTTONS
PRESS_THRESHOLD = 0.5


def value_range(element: str) -> tuple[float, float]:
    """The values *element* can take: sticks [-1, 1], triggers and buttons [0, 1]."""
    return (-1.0, 1.0) if element in STICK_AXES else (0.0, 1.0)


class PadSpecError(BadInput):
    """A gamepad timeline entry that cannot be read; the message quotes it."""


@dataclass(frozen=True)
class PadChange:
    """One timeline entry: from *time* on, *element* of pad *pad* reads *value*."""

    element: str
    value: float
    time: float
    pad: int = 0


@dataclass(frozen=True)
class PadSnapshot:
    """What the gamepads did during one physics step: changes in order, then every value now."""

    step: int
    connected: frozenset[int]
    changes: tuple[tuple[int, str, float], ...]
    values: Mapping[tuple[int, str], float]

    def value(self, pad: int, element: str) -> float:
        return self.values.get((pad, element), 0.0)


class PadSource(Protocol):
    connected: frozenset[int]

    def poll(self, time: float) -> list[tuple[int, str, float]]:
        """Changes ``(pad, element, value)`` that happened up to simulated *time*, in order."""


class NeutralPad:
    """Pad 0 with nothing moving: headless runs without a timeline, and the GUI."""

    connected = frozenset({0})

    def poll(self, time: float) -> list[tuple[int, str, float]]:
        return []


class ScriptedPad:
    """A gamepad timeline replayed against simulated time; values hold until the next entry.

    Entries due at a poll are delivered in time order (file order for equal times).
    """

    def __init__(self, changes: Iterable[PadChange]):
        indexed = sorted(enumerate(changes), key=lambda pair: (pair[1].time, pair[0]))
        self.changes = tuple(change for _, change in indexed)
        self.connected = frozenset({0} | {change.pad for change in self.changes})
        self._next = 0

    def poll(self, time: float) -> list[tuple[int, str, float]]:
        due = []
        while self._next < len(self.changes) and self.changes[self._next].time <= time + 1e-9:
            change = self.changes[self._next]
            due.append((change.pad, change.element, change.value))
            self._next += 1
        return due

    def rewind(self) -> None:
        self._next = 0


def make_change(element, value, time, pad=0, *, where: str) -> PadChange:
    """A checked ``PadChange``; *where* names the entry in error messages."""
    if element not in ELEMENTS:
        raise PadSpecError(f"{where}: unknown gamepad element {element!r} (Kit names: "
                           f"{', '.join(STICK_AXES + TRIGGERS)}, Face Button Bottom, D-Pad Up, ...)")
    if isinstance(pad, bool) or not isinstance(pad, int) or pad < 0:
        raise PadSpecError(f"{where}: gamepad id must be an integer >= 0, got {pad!r}")
    for name, number in (("value", value), ("time", time)):
        if isinstance(number, bool) or not isinstance(number, (int, float)):
            raise PadSpecError(f"{where}: {name} must be a number, got {number!r}")
    low, high = value_range(element)
    if not low <= value <= high:
        raise PadSpecError(f"{where}: {element} takes values in [{low:g}, {high:g}], got {value!r}")
    if time < 0:
        raise PadSpecError(f"{where}: time must be >= 0 s, got {time!r}")
    return PadChange(element, float(value), float(time), pad)


_NUMBER = r"[-+]?[0-9]*\.?[0-9]+(?:[eE][+-]?[0-9]+)?"
_SPEC_PATTERN = re.compile(rf"^(?:(?P<pad>[0-9]+):)?(?P<element>[^=:@]+)=(?P<value>{_NUMBER})@(?P<time>{_NUMBER})$")


def parse_pad_spec(text: str) -> PadChange:
    """``Left Stick X Axis=0.5@1.0`` (pad 0) or ``1:Face Button Bottom=1@2.5`` (pad 1): ELEMENT=VALUE@TIME."""
    match = _SPEC_PATTERN.match(text.strip())
    if not match:
        raise PadSpecError(f"pad {text!r}: expected ELEMENT=VALUE@TIME, e.g. \"Right Stick Y Axis=-1@0.5\"")
    pad = int(match["pad"]) if match["pad"] is not None else 0
    return make_change(match["element"].strip(), float(match["value"]), float(match["time"]), pad,
                       where=f"pad {text!r}")


def load_pad_timeline(path: str | Path) -> list[PadChange]:
    """Read a gamepad file: ``{"gamepad": [{"element": ..., "time": s, "value": v, "pad": 0}, ...]}``."""
    entries = timeline_entries(path, "gamepad", ("element", "time", "value"), ("pad",), PadSpecError,
                               '{"element": ..., "time": ..., "value": ...}')
    return [make_change(entry["element"], entry["value"], entry["time"], entry.get("pad", 0), where=where)
            for where, entry in entries]


def scripted_pad(path: str | Path | None, specs: Iterable[str] = ()) -> ScriptedPad | None:
    """The timeline of ``graphflow run --gamepad FILE --pad SPEC ...`` (file entries first), or None if neither is given."""
    changes = load_pad_timeline(path) if path is not None else []
    changes.extend(parse_pad_spec(spec) for spec in specs)
    if path is None and not changes:
        return None
    return ScriptedPad(changes)


class Gamepad(StepPolledDevice[PadSnapshot]):
    """The gamepad state of one world: polls its source once per physics step and remembers values."""

    def __init__(self, source: PadSource, world):
        self._values: dict[tuple[int, str], float] = {}
        super().__init__(source, world)

    def _advance(self, step: int, changes: tuple) -> PadSnapshot:
        for pad, element, value in changes:
            self._values[(pad, element)] = value
        return PadSnapshot(step, self.source.connected, changes, dict(self._values))

    def _forget(self) -> None:
        self._values.clear()


def attach_gamepad(world, source: PadSource) -> Gamepad:
    """Make *source* the gamepad of *world* (replacing any earlier one)."""
    return world.services.add(Gamepad(source, world))


def gamepad_for(world) -> Gamepad:
    """The gamepad of *world*; by default one neutral pad."""
    return world.services.require(Gamepad, lambda: Gamepad(NeutralPad(), world))
