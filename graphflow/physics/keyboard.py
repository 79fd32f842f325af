"""The PyBullet GUI window as a graphflow key source (see graphflow.inputs.keyboard).

PyBullet reports keys as codes with flags; this turns them into Kit key
tokens. It has one Shift, Ctrl and Alt, reported as the left-hand keys. The
PyBullet window also uses some letters itself (w wireframe, g grid, ...).
In DIRECT mode PyBullet reports no keys at all (pybullet_notes §3e).
"""
from __future__ import annotations

from typing import Callable

import pybullet

_SPECIAL_KEYS = {
    pybullet.B3G_UP_ARROW: "Up", pybullet.B3G_DOWN_ARROW: "Down",
    pybullet.B3G_LEFT_ARROW: "Left", pybullet.B3G_RIGHT_ARROW: "Right",
    pybullet.B3G_PAGE_UP: "PageUp", pybullet.B3G_PAGE_DOWN: "PageDown",
    pybullet.B3G_HOME: "Home", pybullet.B3G_END: "End", pybullet.B3G_INSERT: "Insert",
    pybullet.B3G_DELETE: "Del", pybullet.B3G_BACKSPACE: "Backspace",
    pybullet.B3G_RETURN: "Enter", pybullet.B3G_SPACE: "Space",
    pybullet.B3G_SHIFT: "LeftShift", pybullet.B3G_CONTROL: "LeftControl", pybullet.B3G_ALT: "LeftAlt",
    9: "Tab", 27: "Escape",
    **{getattr(pybullet, f"B3G_F{number}"): f"F{number}" for number in range(1, 13)},
    **{ord(chr(code).lower()): chr(code) for code in range(ord("A"), ord("Z") + 1)},
    **{ord(str(digit)): f"Key{digit}" for digit in range(10)},
}


def key_token(code: int) -> str | None:
    """Kit's name for a PyBullet key code, or None for keys graphflow does not name."""
    return _SPECIAL_KEYS.get(code)


class PyBulletKeys:
    """Reads ``getKeyboardEvents`` once per poll; a key pressed and released within one poll gives both."""

    def __init__(self, read_events: Callable[[], dict]):
        self.read_events = read_events

    def poll(self, time: float) -> list[tuple[str, bool]]:
        transitions = []
        for code, flags in sorted(self.read_events().items()):
            token = key_token(code)
            if token is None:
                continue
            if flags & pybullet.KEY_WAS_TRIGGERED:
                transitions.append((token, True))
            if flags & pybullet.KEY_WAS_RELEASED:
                transitions.append((token, False))
        return transitions

