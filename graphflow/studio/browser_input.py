"""Key presses, gamepad controls and mouse events from the studio's page, as sources of graphflow.inputs' services.

The page sends what the browser reports (``KeyboardEvent.code``: ``KeyA``, ``ArrowUp``, ``ShiftLeft``);
here it becomes Kit's key names (``A``, ``Up``, ``LeftShift``), the tokens ``OnKeyboardInput`` reads,
so a graph sees the same keys from a browser tab as from the PyBullet window. Events arrive on the
server's thread and are polled by the run's thread at its next physics step. What each poll handed
over is kept, with the simulated time of the poll, as a scripted timeline (``timeline()``): replayed,
it gives the run exactly the same input, which is how a live run's trace is made again when saved.
"""
from __future__ import annotations

import threading

from graphflow.errors import BadInput
from graphflow.inputs.gamepad import ELEMENTS, PadChange, ScriptedPad, value_range
from graphflow.inputs.keyboard import KEY_TOKENS, KeyAction, ScriptedKeys
from graphflow.inputs.mouse import MouseSpecError, ScriptedMouse, make_change

_NAMED_CODES = {
    "ArrowUp": "Up", "ArrowDown": "Down", "ArrowLeft": "Left", "ArrowRight": "Right", "Delete": "Del",
    "ShiftLeft": "LeftShift", "ShiftRight": "RightShift", "ControlLeft": "LeftControl",
    "ControlRight": "RightControl", "AltLeft": "LeftAlt", "AltRight": "RightAlt", "MetaLeft": "LeftSuper",
    "MetaRight": "RightSuper", "ContextMenu": "Menu", "Quote": "Apostrophe",
    "BracketLeft": "LeftBracket", "BracketRight": "RightBracket", "Backquote": "GraveAccent",
    "NumpadDecimal": "NumpadDel",
}
_KEYS = frozenset(KEY_TOKENS)


def kit_key(code: str) -> str | None:
    """Kit's name of a browser ``KeyboardEvent.code`` (None: a key Kit does not name)."""
    if not isinstance(code, str):
        return None
    if code.startswith("Key") and len(code) == 4:
        name = code[3]
    elif code.startswith("Digit") and len(code) == 6:
        name = f"Key{code[5]}"
    else:
        name = _NAMED_CODES.get(code, code)
    return name if name in _KEYS else None


class _Pending:
    """Changes queued by the server thread, handed over whole at the run thread's poll."""

    def __init__(self):
        self._lock = threading.Lock()
        self._changes: list = []
        self.delivered: list[tuple[float, list]] = []   # (simulated time of the poll, what it handed over)

    def push(self, change) -> None:
        with self._lock:
            self._changes.append(change)

    def poll(self, time: float) -> list:
        with self._lock:
            changes, self._changes = self._changes, []
        if changes:
            self.delivered.append((time, changes))
        return changes

    def rewind(self) -> None:
        """A reset run starts with no queued input (keys still held in the page are sent again when released)."""
        with self._lock:
            self._changes = []
        self.delivered = []


class BrowserKeys(_Pending):
    """A ``KeySource`` fed by the page: ``press(code, down)``."""

    def press(self, code: str, down: bool) -> str:
        key = kit_key(code)
        if key is None:
            raise BadInput(f"key {code!r}: not a key OnKeyboardInput knows (Kit key names)")
        self.push((key, bool(down)))
        return key

    def timeline(self) -> ScriptedKeys:
        """The keys delivered so far as a scripted timeline: each transition at the time of the poll that got it."""
        return ScriptedKeys([KeyAction(key, time, "down" if down else "up")
                             for time, changes in self.delivered for key, down in changes])


class BrowserPad(_Pending):
    """A ``PadSource`` fed by the page's on-screen gamepad (pad 0, the one always connected): ``move(element, value)``."""

    connected = frozenset({0})

    def move(self, element: str, value: float) -> None:
        if element not in ELEMENTS:
            raise BadInput(f"gamepad element {element!r} is not one the gamepad nodes read")
        low, high = value_range(element)
        if isinstance(value, bool) or not isinstance(value, (int, float)) or not low <= value <= high:
            raise BadInput(f"gamepad {element}: {value!r} is outside [{low}, {high}]")
        self.push((0, element, float(value)))

    def timeline(self) -> ScriptedPad:
        """The pad changes delivered so far as a scripted timeline, each at the time of the poll that got it."""
        return ScriptedPad([PadChange(element, value, time, pad)
                            for time, changes in self.delivered for pad, element, value in changes])


class BrowserMouse(_Pending):
    """A ``MouseSource`` fed by the page: ``event(element, value)`` as a mouse timeline entry (Kit's buttons 1/0,
    ``Position`` [x, y] normalized to the page's view, ``Scroll`` [dx, dy]). The page does not send these yet."""

    def event(self, element: str, value) -> None:
        try:
            change = make_change(element, value, 0.0, where="mouse")
        except MouseSpecError as error:
            raise BadInput(str(error)) from None
        self.push((change.element, change.value))

    def timeline(self) -> ScriptedMouse:
        """The mouse events delivered so far as a scripted timeline, each at the time of the poll that got it."""
        return ScriptedMouse([make_change(element, value, time, where="mouse")
                              for time, changes in self.delivered for element, value in changes])
