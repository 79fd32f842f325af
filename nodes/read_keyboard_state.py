"""omni.graph.nodes.ReadKeyboardState: whether a key, and each modifier, is held now.

Keys come from the world's keyboard (``graphflow.keyboard``), polled once per
physics step: the PyBullet window with ``--gui``, a scripted timeline headless.
"""
from graphflow.inputs.keyboard import KEY_TOKENS, MODIFIER_KEYS, keyboard_for
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.ReadKeyboardState",
    version=1,
    description=(
        "outputs:isPressed = the key is held at the end of this physics step; shiftOut, ctrlOut and altOut "
        "= either variant of that modifier is held."),
    categories=("input:keyboard",),
    ui_name="Read Keyboard State",
    inputs=(
        Attribute("key", "token", default="A", allowed_tokens=KEY_TOKENS, description="The key (Kit key names)"),
    ),
    outputs=(
        Attribute("isPressed", "bool", description="The key is held"),
        Attribute("shiftOut", "bool", description="A Shift key is held"),
        Attribute("ctrlOut", "bool", description="A Ctrl key is held"),
        Attribute("altOut", "bool", description="An Alt key is held"),
    ),
)


def compute(db):
    held = keyboard_for(db.world).snapshot().held
    db.outputs.isPressed = db.inputs.key in held
    db.outputs.shiftOut, db.outputs.ctrlOut, db.outputs.altOut = (
        any(variant in held for variant in MODIFIER_KEYS[name]) for name in ("shift", "ctrl", "alt"))
