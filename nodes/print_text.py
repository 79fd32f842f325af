"""omni.graph.ui_nodes.PrintText: log a line of text when pulsed."""
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState

LEVELS = {"Info": "info", "Warning": "warning", "Error": "error"}

SPEC = NodeSpec(
    id="omni.graph.ui_nodes.PrintText",
    version=1,
    description=(
        "On an execIn pulse, writes 'text' to the run's log at logLevel "
        "(Info, Warning or Error) and fires execOut. An Error-level line is only "
        "logged; it does not stop the graph. toScreen and viewport are Kit's on-screen "
        "copy of the line: a graphflow run has no viewport, so the log is where it goes."),
    categories=("debug",),
    ui_name="Print Text",
    inputs=(
        Attribute("execIn", "execution", description="Input execution"),
        Attribute("text", "string", default="", description="The text to print"),
        Attribute("logLevel", "token", default="Info", allowed_tokens=tuple(LEVELS),
                  description="Info, Warning or Error"),
        Attribute("toScreen", "bool", default=False,
                  description="Kit also shows the text on a viewport (none here: logged either way)"),
        Attribute("viewport", "token", default="", description="Kit's viewport for toScreen (none here)"),
    ),
    outputs=(
        Attribute("execOut", "execution", description="Fires after printing"),
    ),
)


def compute(db):
    if db.inputs.execIn != ExecState.ENABLED:
        return
    db.log(db.inputs.text, level=LEVELS.get(db.inputs.logLevel, "info"))
    db.outputs.execOut = ExecState.ENABLED
