"""Keyboard input for graphs: one key-state service per world, fed by a pluggable source.

``OnKeyboardInput`` nodes never talk to a device. They ask
``keyboard_for(db.world)`` (a service the world owns) for the tick's
``KeySnapshot``: the ordered key transitions since the previous physics step
and the keys held now. The ``Keyboard`` polls its source at most once per
physics step, so every node of every graph instance sees the same events in
the same tick, whoever asks first.

Sources (all return ordered ``(key, is_down)`` transitions for a poll at a
simulated time, never reading the wall clock):

* ``ScriptedKeys`` - a timeline for headless runs and tests
  (``graphflow run --keys FILE`` / ``--key A@1.5``);
* ``graphflow.physics.keyboard.PyBulletKeys`` - the PyBullet GUI window;
* nothing attached: the world's own window keys (``world.window_keys()``:
  the PyBullet window; DIRECT clients report no keys), else no keys.

Key names are Kit's ``carb.input.KeyboardInput`` tokens (``A``, ``Key1``,
``Up``, ``PageDown``, ``LeftShift``...), as in OmniGraph's ``inputs:keyIn``.
"""
from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path
from typing import Iterable, Protocol

from graphflow.errors import BadInput
from graphflow.inputs.device import StepPolledDevice

LETTERS = tuple(chr(code) for code in range(ord("A"), ord("Z") + 1))
DIGITS = tuple(f"Key{digit}" for digit in range(10))
FUNCTION_KEYS = tuple(f"F{number}" for number in range(1, 13))
MODIFIER_KEYS = {
    "shift": ("LeftShift", "RightShift"),
    "ctrl": ("LeftControl", "RightControl"),
    "alt": ("LeftAlt", "RightAlt"),
}
# Kit's OnKeyboardInput allowedTokens (carb.input.KeyboardInput names)
KEY_TOKENS = LETTERS + DIGITS + FUNCTION_KEYS + (
    "Up", "Down", "Left", "Right", "PageUp", "PageDown", "Home", "End", "Insert", "Del",
    "Space", "Enter", "Escape", "Tab", "Backspace", "CapsLock", "ScrollLock", "NumLock",
    "PrintScreen", "Pause", "Menu",
    "LeftShift", "RightShift", "LeftControl", "RightControl", "LeftAlt", "RightAlt",
    "LeftSuper", "RightSuper",
    "Apostrophe", "Comma", "Minus", "Period", "Slash", "Semicolon", "Equal",
    "LeftBracket", "Backslash", "RightBracket", "GraveAccent",
) + tuple(f"Numpad{digit}" for digit in range(10)) + (
    "NumpadAdd", "NumpadSubtract", "NumpadMultiply", "NumpadDivide", "NumpadDel",
    "NumpadEnter", "NumpadEqual",
)
_KEY_SET = frozenset(KEY_TOKENS)


class KeySpecError(BadInput):
    """A key timeline entry that cannot be read; the message quotes it."""


@dataclass(frozen=True)
class KeySnapshot:
    """What the keyboard did during one physics step: transitions in order, then what is held."""

    step: int
    held_before: frozenset[str]
    transitions: tuple[tuple[str, bool], ...]
    held: frozenset[str]


class KeySource(Protocol):
    def poll(self, time: float) -> list[tuple[str, bool]]:
        """Transitions ``(key, is_down)`` that happened up to simulated *time*, in order."""


class NoKeys:
    """A source with no keyboard: headless runs without a timeline."""

    def poll(self, time: float) -> list[tuple[str, bool]]:
        return []


@dataclass(frozen=True)
class KeyAction:
    """One timeline entry: ``down`` / ``up`` at a time, or a ``tap`` (down, then up one step later)."""

    key: str
    time: float
    kind: str   # "down", "up" or "tap"


class ScriptedKeys:
    """A key timeline replayed against simulated time, for headless runs and tests.

    Entries due at a poll are delivered in time order (file order for equal
    times). A tap goes down at its time and up at the following poll, so it is
    held for exactly one physics step whatever the step length.
    """

    def __init__(self, actions: Iterable[KeyAction]):
        indexed = sorted(enumerate(actions), key=lambda pair: (pair[1].time, pair[0]))
        self.actions = tuple(action for _, action in indexed)
        self._next = 0
        self._pending_up: list[str] = []

    def poll(self, time: float) -> list[tuple[str, bool]]:
        transitions = [(key, False) for key in self._pending_up]
        self._pending_up = []
        while self._next < len(self.actions) and self.actions[self._next].time <= time + 1e-9:
            action = self.actions[self._next]
            self._next += 1
            if action.kind == "up":
                transitions.append((action.key, False))
            else:
                transitions.append((action.key, True))
                if action.kind == "tap":
                    self._pending_up.append(action.key)
        return transitions

    def rewind(self) -> None:
        self._next = 0
        self._pending_up = []


_NUMBER = r"[0-9]*\.?[0-9]+(?:[eE][+-]?[0-9]+)?"
_SPEC_PATTERN = re.compile(
    rf"^(?P<key>[A-Za-z0-9]+)@(?P<start>{_NUMBER})(?:-(?P<end>{_NUMBER})|:(?P<kind>down|up|tap))?$")


def parse_key_spec(text: str) -> list[KeyAction]:
    """``A@1.5`` tap, ``A@1.5:down`` / ``A@1.5:up``, ``Up@1.0-2.5`` held from 1.0 s to 2.5 s."""
    match = _SPEC_PATTERN.match(text.strip())
    if not match:
        raise KeySpecError(f"key {text!r}: expected KEY@TIME, KEY@TIME:down, KEY@TIME:up or KEY@START-END")
    key = match["key"]
    if key not in _KEY_SET:
        raise KeySpecError(f"key {text!r}: unknown key {key!r} (Kit key names: A-Z, Key0-Key9, F1-F12, "
                           f"Up, Down, Left, Right, PageUp, PageDown, Space, Enter, LeftShift, ...)")
    start = float(match["start"])
    if match["end"] is not None:
        end = float(match["end"])
        if end <= start:
            raise KeySpecError(f"key {text!r}: the release time must come after the press time")
        return [KeyAction(key, start, "down"), KeyAction(key, end, "up")]
    return [KeyAction(key, start, match["kind"] or "tap")]


def load_key_timeline(path: str | Path) -> list[KeyAction]:
    """Read a key file: ``{"keys": ["A@1.5", "Up@2.0-3.0", ...]}`` (same syntax as ``--key``)."""
    from graphflow.files import FileProblem, read_json

    try:
        data = read_json(path)   # strict JSON, regular files only (never /dev/zero)
    except FileProblem as error:
        raise KeySpecError(str(error)) from None
    entries = data.get("keys") if isinstance(data, dict) else None
    if not isinstance(entries, list) or not all(isinstance(entry, str) for entry in entries):
        raise KeySpecError(f"{path}: expected an object with a 'keys' list of strings such as \"A@1.5\"")
    actions = []
    for entry in entries:
        try:
            actions.extend(parse_key_spec(entry))
        except KeySpecError as error:
            raise KeySpecError(f"{path}: {error}") from None
    return actions


def scripted_keys(path: str | Path | None, specs: Iterable[str] = ()) -> ScriptedKeys | None:
    """The timeline of ``graphflow run --keys FILE --key SPEC ...`` (file entries first), or None if neither is given."""
    actions = load_key_timeline(path) if path is not None else []
    for spec in specs:
        actions.extend(parse_key_spec(spec))
    if path is None and not actions:
        return None
    return ScriptedKeys(actions)


class Keyboard(StepPolledDevice[KeySnapshot]):
    """The key state of one world: polls its source once per physics step and remembers held keys."""

    def __init__(self, source: KeySource, world):
        self._held: set[str] = set()
        super().__init__(source, world)

    def _advance(self, step: int, transitions: tuple) -> KeySnapshot:
        held_before = frozenset(self._held)
        for key, is_down in transitions:
            (self._held.add if is_down else self._held.discard)(key)
        return KeySnapshot(step, held_before, transitions, frozenset(self._held))

    def _forget(self) -> None:
        self._held.clear()


def attach_keyboard(world, source: KeySource) -> Keyboard:
    """Make *source* the keyboard of *world* (replacing any earlier one)."""
    return world.services.add(Keyboard(source, world))


def keyboard_for(world) -> Keyboard:
    """The keyboard of *world*; by default its window's keys (``world.window_keys()``), else no keys."""
    return world.services.require(Keyboard, lambda: Keyboard(world.window_keys() or NoKeys(), world))
