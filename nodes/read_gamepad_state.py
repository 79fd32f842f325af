"""omni.graph.nodes.ReadGamepadState: one gamepad element's value this tick.

Reads the world's gamepad (``graphflow.inputs.gamepad``), polled once per physics
step, so every reader in a tick sees the same pad. Values inside the deadzone
read 0, so a resting stick does not drift what it drives.
"""
from graphflow.inputs.gamepad import BUTTONS, ELEMENTS, PRESS_THRESHOLD, gamepad_for
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.ReadGamepadState",
    version=1,
    description=(
        "Outputs the value of gamepadElement on pad gamepadId: sticks in [-1, 1], "
        "triggers and buttons in [0, 1], 0 while |value| <= deadzone. isPressed: a button is "
        "pressed at value >= 0.5, a stick or trigger when it is out of the deadzone. A gamepadId "
        "that is not connected is a run-time error."),
    categories=("input:gamepad",),
    ui_name="Read Gamepad State",
    inputs=(
        Attribute("gamepadElement", "token", default="Left Stick X Axis", allowed_tokens=ELEMENTS,
                  description="The gamepad element whose state is read"),
        Attribute("gamepadId", "uint", default=0, description="Gamepad id number starting from 0"),
        Attribute("deadzone", "float", default=0.1,
                  description="Threshold in [0, 1] the value must pass to register as input"),
    ),
    outputs=(
        Attribute("value", "float", description="How far the element is pushed; 0 inside the deadzone"),
        Attribute("isPressed", "bool", description="True while the element is pressed"),
    ),
)


def compute(db):
    snapshot = gamepad_for(db.world).snapshot()
    pad, element = db.inputs.gamepadId, db.inputs.gamepadElement
    if pad not in snapshot.connected:
        db.error(f"inputs:gamepadId: no gamepad {pad} (connected: {', '.join(map(str, sorted(snapshot.connected)))})")
    raw = snapshot.value(pad, element)
    outside_deadzone = abs(raw) > db.inputs.deadzone
    db.outputs.value = raw if outside_deadzone else 0.0
    db.outputs.isPressed = raw >= PRESS_THRESHOLD if element in BUTTONS else outside_deadzone
