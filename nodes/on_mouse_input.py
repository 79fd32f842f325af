"""omni.graph.action.OnMouseInput: fire on a mouse button's press and release, or on a move or scroll.

The mouse is the world's (``graphflow.inputs.mouse``): a scripted timeline
(``--mouse`` / ``--click``, or the graph's scenario). Headless without one
nothing ever clicks or moves, so this node never fires. A press and a release
within one physics step fire both, pressed first; several moves (or scrolls)
in one step fire valueChanged once, with the last position (the summed scroll).
"""
from graphflow.inputs.mouse import BUTTONS, POSITION, SCROLL, WINDOW_PIXELS, mouse_for
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState

MOVES = {"Normalized Move": (1.0, 1.0), "Pixel Move": WINDOW_PIXELS}
ELEMENTS = ("Left Button", "Middle Button", "Right Button", "Normalized Move", "Pixel Move", "Scroll")

SPEC = NodeSpec(
    id="omni.graph.action.OnMouseInput",
    version=2,
    compatible_versions=(1,),
    description=(
        "Event source. For a button mouseElement: 'pressed' fires when it goes down, 'released' when it goes "
        "up, isPressed between. For Normalized Move / Pixel Move: 'valueChanged' fires when the pointer moved, "
        "value = its position (normalized, or pixels of graphflow's nominal 1280x720 window), (0, 0) top left. "
        "For Scroll: 'valueChanged' fires on a scroll, value = the scroll's change. Headless with no scripted "
        "mouse (--mouse, --click) it never fires; onlyPlayback has no effect (graphflow graphs only tick while "
        "running)."),
    categories=("graph:action", "input:mouse"),
    ui_name="On Mouse Input",
    inputs=(
        Attribute("mouseElement", "token", default="Left Button", allowed_tokens=ELEMENTS,
                  description="The name of the mouse event that will trigger the downstream execution"),
        Attribute("onlyPlayback", "bool", default=True,
                  description="Only compute while playing (graphflow always plays while running)"),
    ),
    outputs=(
        Attribute("isPressed", "bool", description="True from a press of the button until its release"),
        Attribute("pressed", "execution", description="Fires when the button was pressed"),
        Attribute("released", "execution", description="Fires when the button was released"),
        Attribute("value", "float[2]", description="Position (moves) or scroll change (Scroll); (0, 0) for buttons"),
        Attribute("valueChanged", "execution", description="Fires when the pointer moved or the wheel scrolled"),
    ),
    state=(
        Attribute("isPressed", "bool", default=False, description="Between a press and its release"),
        Attribute("lastStep", "int", default=-1, description="Physics step whose mouse events were handled"),
    ),
)


def compute(db):
    snapshot = mouse_for(db.world).snapshot()
    if snapshot.step != db.state.lastStep:
        db.state.lastStep = snapshot.step
        element = db.inputs.mouseElement
        if element in BUTTONS:
            _buttons(db, element, snapshot.changes)
        elif element in MOVES:
            _move(db, element, snapshot)
        else:
            _scroll(db, snapshot.changes)
    db.outputs.isPressed = db.state.isPressed


def _buttons(db, button, changes):
    for element, value in changes:
        if element != button:
            continue
        if value and not db.state.isPressed:
            db.state.isPressed = True
            db.outputs.pressed = ExecState.ENABLED
        elif not value and db.state.isPressed:
            db.state.isPressed = False
            db.outputs.released = ExecState.ENABLED


def _move(db, element, snapshot):
    if any(changed == POSITION for changed, _ in snapshot.changes):
        scale = MOVES[element]
        db.outputs.value = (snapshot.position[0] * scale[0], snapshot.position[1] * scale[1])
        db.outputs.valueChanged = ExecState.ENABLED


def _scroll(db, changes):
    deltas = [value for element, value in changes if element == SCROLL]
    if deltas:
        db.outputs.value = (sum(d[0] for d in deltas), sum(d[1] for d in deltas))
        db.outputs.valueChanged = ExecState.ENABLED
