"""omni.graph.visualization.nodes.DrawScreenSpaceText: viewport text, written to the run's log headless.

Kit redraws the label every pulse; a headless run has no viewport, so the
text goes to the log once and again only when it changes (a per-tick pulse
would otherwise print it every tick); an empty label shows nothing. Colour, size, box width and position
only matter in a viewport; they are accepted and not drawn.
"""
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState

SPEC = NodeSpec(
    id="omni.graph.visualization.nodes.DrawScreenSpaceText",
    version=1,
    description=(
        "On an execIn pulse, shows 'text' (headless: logs it when it differs from the last text "
        "logged; empty text logs nothing) and fires execOut. textColor, backgroundColor, size, boxWidth and position are "
        "viewport styling, not drawn headless."),
    categories=("graph:action", "sceneGraph:visualization"),
    ui_name="Draw Screen Space Text (Beta)",
    inputs=(
        Attribute("execIn", "execution", description="Input execution"),
        Attribute("text", "string", default="", description="Label text"),
        Attribute("textColor", "colorf[4]", default=(0.95, 0.95, 0.95, 1.0), description="Text color"),
        Attribute("backgroundColor", "colorf[4]", default=(0.165, 0.157, 0.145, 0.8), description="Background color"),
        Attribute("size", "float", default=14.0, description="Text size"),
        Attribute("boxWidth", "int", default=0, description="Text box width before wrapping (0: no wrapping)"),
        Attribute("position", "double[2]", default=(50.0, 50.0),
                  description="Text position on the viewport, in percent of its size"),
    ),
    outputs=(
        Attribute("execOut", "execution", description="Fires after the text is shown"),
    ),
    state=(
        Attribute("shownText", "string", default="", description="The text logged last"),
    ),
)


def compute(db):
    if db.inputs.execIn != ExecState.ENABLED:
        return
    text = db.inputs.text
    if text != db.state.shownText:
        db.log(text)
        db.state.shownText = text
    db.outputs.execOut = ExecState.ENABLED
