"""omni.graph.action.OnGamepadInput: fire on a gamepad button press and on its release.

Pad values come from the world's gamepad (``graphflow.inputs.gamepad``): a scripted
timeline headless (``--gamepad`` / ``--pad``), else one neutral pad. A button
counts as down while its value is at least 0.5, so an analog button crossing
the threshold presses once and releases once.
"""
from graphflow.inputs.gamepad import BUTTONS, PRESS_THRESHOLD, gamepad_for
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState

SPEC = NodeSpec(
    id="omni.graph.action.OnGamepadInput",
    version=2,
    description=(
        "Event source. 'pressed' fires once when gamepadElementIn of pad gamepadId goes down "
        "(value >= 0.5), 'released' once when it goes up; a press and release within one physics "
        "step fire both, pressed first. Buttons only, no sticks or triggers. A gamepadId that is "
        "not connected is a run-time error. graphflow graphs only tick while running, so "
        "onlyPlayback has no effect."),
    categories=("graph:action", "input:gamepad"),
    ui_name="On Gamepad Input",
    inputs=(
        Attribute("gamepadElementIn", "token", default="Face Button Bottom", allowed_tokens=BUTTONS,
                  description="The gamepad button that triggers the downstream execution"),
        Attribute("gamepadId", "uint", default=0, description="Gamepad id number starting from 0"),
        Attribute("onlyPlayback", "bool", default=True,
                  description="Only compute while playing (graphflow always plays while running)"),
    ),
    outputs=(
        Attribute("pressed", "execution", description="Fires when the button was pressed"),
        Attribute("released", "execution", description="Fires when the button was released after a press"),
        Attribute("isPressed", "bool", description="True from the press until the release"),
    ),
    state=(
        Attribute("isPressed", "bool", default=False, description="Between a press and its release"),
        Attribute("lastStep", "int", default=-1, description="Physics step whose pad changes were handled"),
    ),
)


def compute(db):
    snapshot = gamepad_for(db.world).snapshot()
    pad = db.inputs.gamepadId
    if pad not in snapshot.connected:
        db.error(f"inputs:gamepadId: no gamepad {pad} (connected: {', '.join(map(str, sorted(snapshot.connected)))})")
    if snapshot.step != db.state.lastStep:
        db.state.lastStep = snapshot.step
        button = db.inputs.gamepadElementIn
        for changed_pad, element, value in snapshot.changes:
            if changed_pad != pad or element != button:
                continue
            down = value >= PRESS_THRESHOLD
            if down and not db.state.isPressed:
                db.outputs.pressed = ExecState.ENABLED
            elif not down and db.state.isPressed:
                db.outputs.released = ExecState.ENABLED
            db.state.isPressed = down
    db.outputs.isPressed = db.state.isPressed
