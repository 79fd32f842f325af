"""Mouse input for graphs: one mouse-state service per world, fed by a scripted timeline.

``OnMouseInput`` and ``ReadMouseState`` nodes never talk to a device. They ask
``mouse_for(db.world)`` for the tick's ``MouseSnapshot``: the ordered changes
since the previous physics step, then the buttons held and the pointer's
position now. The ``Mouse`` polls its source at most once per physics step, so
every node sees the same events in the same tick. Nothing reads the wall clock.

What is modelled: one application window of ``WINDOW_PIXELS`` (a nominal
1280 x 720; Kit's pixel coordinates depend on the real window, which a headless
run does not have), the pointer's position in it (normalized, (0, 0) top left,
(1, 1) bottom right), Kit's five buttons and the scroll wheel (deltas).

Sources (ordered ``(element, value)`` changes for a poll at a simulated time):

* ``ScriptedMouse`` - a timeline for headless runs and tests
  (``graphflow run --mouse FILE`` / ``--click "Left Button=1@0.5"``);
* nothing attached: no mouse. Nothing ever moves or clicks, so OnMouseInput
  never fires and ReadMouseState reads no button held, the pointer at (0, 0).
  The PyBullet window's mouse is not read.

Timeline entries: a button (``Left Button``, ``Middle Button``, ``Right Button``,
``Forward Button``, ``Back Button``) with value 1 (down) or 0 (up); ``Position``
with ``[x, y]`` normalized (each in [0, 1]); ``Scroll`` with ``[dx, dy]``, one
scroll event of that size.
"""
from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path
from typing import Iterable, Protocol

from graphflow.errors import BadInput
from graphflow.inputs.device import StepPolledDevice, timeline_entries

BUTTONS = ("Left Button", "Middle Button", "Right Button", "Forward Button", "Back Button")
POSITION, SCROLL = "Position", "Scroll"
ELEMENTS = BUTTONS + (POSITION, SCROLL)
WINDOW_PIXELS = (1280.0, 720.0)


class MouseSpecError(BadInput):
    """A mouse timeline entry that cannot be read; the message quotes it."""


@dataclass(frozen=True)
class MouseChange:
    """One timeline entry: at *time*, *element* takes *value* (0/1 for a button, (x, y) otherwise)."""

    element: str
    value: float | tuple[float, float]
    time: float


@dataclass(frozen=True)
class MouseSnapshot:
    """What the mouse did during one physics step: changes in order, then the state now."""

    step: int
    changes: tuple[tuple[str, object], ...]
    held_before: frozenset[str]
    held: frozenset[str]
    position: tuple[float, float]

    def pixels(self) -> tuple[float, float]:
        """The pointer's position in the nominal window, pixels from its top left corner."""
        return (self.position[0] * WINDOW_PIXELS[0], self.position[1] * WINDOW_PIXELS[1])


class MouseSource(Protocol):
    def poll(self, time: float) -> list[tuple[str, object]]:
        """Changes ``(element, value)`` that happened up to simulated *time*, in order."""


class NoMouse:
    """No mouse: headless runs without a timeline never see a click or a move."""

    def poll(self, time: float) -> list[tuple[str, object]]:
        return []


class ScriptedMouse:
    """A mouse timeline replayed against simulated time, in time order (file order for equal times)."""

    def __init__(self, changes: Iterable[MouseChange]):
        indexed = sorted(enumerate(changes), key=lambda pair: (pair[1].time, pair[0]))
        self.changes = tuple(change for _, change in indexed)
        self._next = 0

    def poll(self, time: float) -> list[tuple[str, object]]:
        due: list[tuple[str, object]] = []
        while self._next < len(self.changes) and self.changes[self._next].time <= time + 1e-9:
            change = self.changes[self._next]
            due.append((change.element, change.value))
            self._next += 1
        return due

    def rewind(self) -> None:
        self._next = 0


def make_change(element, value, time, *, where: str) -> MouseChange:
    """A checked ``MouseChange``; *where* names the entry in error messages."""
    if element not in ELEMENTS:
        raise MouseSpecError(f"{where}: unknown mouse element {element!r} (one of: {', '.join(ELEMENTS)})")
    if isinstance(time, bool) or not isinstance(time, (int, float)) or time < 0:
        raise MouseSpecError(f"{where}: time must be a number >= 0 s, got {time!r}")
    if element in BUTTONS:
        if isinstance(value, bool) or value not in (0, 1):
            raise MouseSpecError(f"{where}: a button is 1 (down) or 0 (up), got {value!r}")
        return MouseChange(element, float(value), float(time))
    pair = tuple(value) if isinstance(value, (list, tuple)) else ()
    if len(pair) != 2 or not all(isinstance(c, (int, float)) and not isinstance(c, bool) for c in pair):
        raise MouseSpecError(f"{where}: {element} takes two numbers [x, y], got {value!r}")
    if element == POSITION and not all(0.0 <= c <= 1.0 for c in pair):
        raise MouseSpecError(f"{where}: Position is normalized, each coordinate in [0, 1], got {value!r}")
    return MouseChange(element, (float(pair[0]), float(pair[1])), float(time))


_NUMBER = r"[-+]?[0-9]*\.?[0-9]+(?:[eE][+-]?[0-9]+)?"
_SPEC_PATTERN = re.compile(
    rf"^(?P<element>[^=@]+)=(?P<value>{_NUMBER}(?:\s*,\s*{_NUMBER})?)@(?P<time>{_NUMBER})$")


def parse_mouse_spec(text: str) -> MouseChange:
    """``Left Button=1@0.5``, ``Position=0.25,0.5@1.0`` or ``Scroll=0,-1@2``: ELEMENT=VALUE@TIME."""
    match = _SPEC_PATTERN.match(text.strip())
    if not match:
        raise MouseSpecError(f"mouse {text!r}: expected ELEMENT=VALUE@TIME, e.g. \"Left Button=1@0.5\" or "
                             f"\"Position=0.25,0.5@1.0\"")
    numbers = [float(part) for part in match["value"].split(",")]
    value = numbers[0] if len(numbers) == 1 else numbers
    return make_change(match["element"].strip(), value, float(match["time"]), where=f"mouse {text!r}")


def load_mouse_timeline(path: str | Path) -> list[MouseChange]:
    """Read a mouse file: ``{"mouse": [{"element": "Left Button", "time": s, "value": 1}, ...]}``."""
    entries = timeline_entries(path, "mouse", ("element", "time", "value"), (), MouseSpecError,
                               '{"element": ..., "time": ..., "value": ...}')
    return [make_change(entry["element"], entry["value"], entry["time"], where=where) for where, entry in entries]


def scripted_mouse(path: str | Path | None, specs: Iterable[str] = ()) -> ScriptedMouse | None:
    """The timeline of ``graphflow run --mouse FILE --click SPEC ...`` (file entries first), or None if neither."""
    changes = load_mouse_timeline(path) if path is not None else []
    changes.extend(parse_mouse_spec(spec) for spec in specs)
    if path is None and not changes:
        return None
    return ScriptedMouse(changes)


class Mouse(StepPolledDevice[MouseSnapshot]):
    """The mouse state of one world: polls its source once per physics step and remembers buttons and position."""

    def __init__(self, source: MouseSource, world):
        self._held: frozenset[str] = frozenset()
        self._position = (0.0, 0.0)
        super().__init__(source, world)

    def _advance(self, step: int, changes: tuple) -> MouseSnapshot:
        before = self._held
        held = set(before)
        for element, value in changes:
            if element in BUTTONS:
                (held.add if value else held.discard)(element)
            elif element == POSITION:
                self._position = value
        self._held = frozenset(held)
        return MouseSnapshot(step, changes, before, self._held, self._position)

    def _forget(self) -> None:
        self._held = frozenset()
        self._position = (0.0, 0.0)


def attach_mouse(world, source: MouseSource) -> Mouse:
    """Make *source* the mouse of *world* (replacing any earlier one)."""
    return world.services.add(Mouse(source, world))


def mouse_for(world) -> Mouse:
    """The mouse of *world*; by default no mouse (nothing ever happens)."""
    return world.services.require(Mouse, lambda: Mouse(NoMouse(), world))
