"""omni.graph.action.OnKeyboardInput: fire on a key press and on its release.

Keys come from the world's keyboard (``graphflow.inputs.keyboard``): the PyBullet
window with ``--gui``, a scripted timeline headless (``--keys`` / ``--key``).

Modifier rule (Kit's source is closed; reference §6.2 leaves it open): the
modifiers must match exactly. An unrequested Shift, Ctrl or Alt held at the
moment the key goes down blocks the press, so bindings for ``A`` and
``Shift+A`` never both fire. Left and right variants count the same.
"""
from graphflow.inputs.keyboard import KEY_TOKENS, MODIFIER_KEYS, keyboard_for
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState

SPEC = NodeSpec(
    id="omni.graph.action.OnKeyboardInput",
    version=3,
    description=(
        "Event source. 'pressed' fires once when keyIn goes down while exactly the "
        "requested modifiers (shiftIn, ctrlIn, altIn) are held; an unrequested "
        "modifier blocks the press. 'released' fires once when keyIn or a required "
        "modifier goes up after a press. A press and release within one physics "
        "step fire both, pressed first. graphflow graphs only tick while running, "
        "so onlyPlayback has no effect."),
    categories=("graph:action", "input:keyboard"),
    ui_name="On Keyboard Input",
    inputs=(
        Attribute("keyIn", "token", default="A", allowed_tokens=KEY_TOKENS,
                  description="The key to watch, without modifiers (Kit key names)"),
        Attribute("shiftIn", "bool", default=False, description="Shift must be held"),
        Attribute("ctrlIn", "bool", default=False, description="Ctrl must be held"),
        Attribute("altIn", "bool", default=False, description="Alt must be held"),
        Attribute("onlyPlayback", "bool", default=True,
                  description="Only compute while playing (graphflow always plays while running)"),
    ),
    outputs=(
        Attribute("pressed", "execution", description="Fires when the key was pressed"),
        Attribute("released", "execution", description="Fires when the key was released after a press"),
        Attribute("isPressed", "bool", description="True from the press until the release"),
        Attribute("keyOut", "token", description="The key that was pressed or released"),
    ),
    state=(
        Attribute("isPressed", "bool", default=False, description="Between a press and its release"),
        Attribute("lastStep", "int", default=-1, description="Physics step whose key events were handled"),
    ),
)


def compute(db):
    snapshot = keyboard_for(db.world).snapshot()
    if snapshot.step != db.state.lastStep:
        db.state.lastStep = snapshot.step
        _handle(db, snapshot)
    db.outputs.isPressed = db.state.isPressed


def _handle(db, snapshot):
    key = db.inputs.keyIn
    required = {name for name, wanted in (("shift", db.inputs.shiftIn), ("ctrl", db.inputs.ctrlIn),
                                          ("alt", db.inputs.altIn)) if wanted}
    watched = {key} | {variant for name in required for variant in MODIFIER_KEYS[name]}
    held = set(snapshot.held_before)
    for changed, is_down in snapshot.transitions:
        (held.add if is_down else held.discard)(changed)
        if is_down and changed == key and not db.state.isPressed and _modifiers_match(held, required, key):
            db.state.isPressed = True
            db.outputs.pressed = ExecState.ENABLED
            db.outputs.keyOut = key
        elif not is_down and db.state.isPressed and changed in watched and not _still_down(held, changed, key):
            db.state.isPressed = False
            db.outputs.released = ExecState.ENABLED
            db.outputs.keyOut = key


def _modifiers_match(held, required, key) -> bool:
    for name, variants in MODIFIER_KEYS.items():
        down = any(variant in held and variant != key for variant in variants)
        if down != (name in required):
            return False
    return True


def _still_down(held, changed, key) -> bool:
    """A required modifier counts as released only when neither its left nor its right key is held."""
    if changed == key:
        return False
    variants = next(v for v in MODIFIER_KEYS.values() if changed in v)
    return any(variant in held for variant in variants)
