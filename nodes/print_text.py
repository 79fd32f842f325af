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
        "logged; it does not stop the graph."),
    categories=("debug",),
    ui_name="Print Text",
    inputs=(
        Attribute("execIn", "execution", description="Input execution"),
        Attribute("text", "string", default="", description="The text to print"),
        Attribute("logLevel", "token", default="Info", allowed_tokens=tuple(LEVELS),
                  description="Info, Warning or Error"),
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
