"""Kit's settings registry headless: a run-local store ReadSetting and WriteSetting share.

Not a node type. Kit's nodes read and write carb settings, the application's
registry of typed values by path ("/app/player/playSimulations"). A graphflow run
has no application, so each world holds its own store (a ``WorldService``),
empty when the run starts and emptied when the world resets: what a graph reads
is what it wrote earlier in the same run, so runs reproduce. Like Kit, a
setting keeps its type: writing a value of another kind fails; reading a path
never written fails too (Kit cannot resolve the output's type and its compute
fails), with a line naming the path rather than a silent zero.
"""
from __future__ import annotations


def kind(value) -> str:
    """The settings type of a value: bool, int, float or string, with '[]' for an array of them."""
    if isinstance(value, tuple):
        kinds = {kind(item) for item in value}
        if len(kinds) > 1 or any(k.endswith("[]") for k in kinds):
            raise ValueError(f"a setting holds one value or a flat array of one type, not {value!r}")
        return (kinds.pop() if kinds else "any") + "[]"
    if isinstance(value, bool):
        return "bool"
    if isinstance(value, int):
        return "int"
    if isinstance(value, float):
        return "float"
    if isinstance(value, str):
        return "string"
    raise ValueError(f"a setting holds a bool, number, string or an array of them, not {type(value).__name__}")


class KitSettings:
    """The settings of one world's run, by path."""

    def __init__(self):
        self._values: dict[str, object] = {}

    def read(self, path: str):
        if path not in self._values:
            raise KeyError(f"setting {path!r} was never written in this run (graphflow has no Kit application "
                           "settings: a WriteSetting must write it before it is read)")
        return self._values[path]

    def write(self, path: str, value) -> None:
        new = kind(value)
        if path in self._values:
            old = kind(self._values[path])
            if new != old and not (new.endswith("[]") and old.endswith("[]") and "any" in (new[:-2], old[:-2])):
                raise ValueError(f"setting {path!r} holds a {old}, not a {new} like {value!r}")
        self._values[path] = value

    def after_step(self, dt: float) -> None:
        """Settings do not change with time."""

    def reset(self) -> None:
        self._values = {}


def kit_settings(db) -> KitSettings:
    return db.world.services.require(KitSettings, KitSettings)
