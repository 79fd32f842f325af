"""omni.graph.nodes.ReadMouseState: whether a mouse button is held now, or where the pointer is.

The mouse is the world's (``graphflow.inputs.mouse``), polled once per physics
step; headless without a scripted mouse no button is held and the pointer is at
(0, 0). graphflow models one window, so useRelativeCoords gives the same
coordinates and outputs:window stays empty (there are no workspace windows).
"""
from graphflow.inputs.mouse import BUTTONS, WINDOW_PIXELS, mouse_for
from graphflow.spec import Attribute, NodeSpec

COORDINATES = {"Normalized Mouse Coordinates": (1.0, 1.0), "Pixel Mouse Coordinates": WINDOW_PIXELS}

SPEC = NodeSpec(
    id="omni.graph.nodes.ReadMouseState",
    version=1,
    aliases=("omni.graph.ui_nodes.ReadMouseState",),
    description=(
        "For a button mouseElement: outputs:isPressed = it is held at the end of this physics step (coords "
        "(0, 0)). For a coordinates element: outputs:coords = the pointer's position, normalized or in pixels "
        "of graphflow's nominal 1280x720 window, (0, 0) top left (isPressed false). One window is modelled: "
        "useRelativeCoords changes nothing and window is empty."),
    categories=("input:mouse",),
    ui_name="Read Mouse State",
    inputs=(
        Attribute("mouseElement", "token", default="Left Button", allowed_tokens=BUTTONS + tuple(COORDINATES),
                  description="The mouse input to check the state of"),
        Attribute("useRelativeCoords", "bool", default=False,
                  description="Coordinates relative to the workspace window (the one window here)"),
    ),
    outputs=(
        Attribute("coords", "float[2]", description="The pointer's coordinates; (0, 0) for a button"),
        Attribute("isPressed", "bool", description="The button is held; false for coordinates"),
        Attribute("window", "token", description="The workspace window's name (empty: one window is modelled)"),
    ),
)


def compute(db):
    snapshot = mouse_for(db.world).snapshot()
    element = db.inputs.mouseElement
    scale = COORDINATES.get(element)
    db.outputs.isPressed = element in snapshot.held
    db.outputs.coords = (0.0, 0.0) if scale is None else (snapshot.position[0] * scale[0],
                                                          snapshot.position[1] * scale[1])
