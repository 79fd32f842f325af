"""omni.graph.action.Once: fire 'once' for the first pulse, 'after' for every later one."""
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState

SPEC = NodeSpec(
    id="omni.graph.action.Once",
    version=1,
    description=(
        "The first execIn pulse fires 'once'; every later pulse fires 'after'. "
        "A reset pulse re-arms the node (the next execIn fires 'once' again) and "
        "fires nothing."),
    categories=("graph:action", "flowControl"),
    ui_name="Once",
    inputs=(
        Attribute("execIn", "execution", description="Input execution"),
        Attribute("reset", "execution", description="Re-arms 'once'"),
    ),
    outputs=(
        Attribute("once", "execution", description="Fires for the first pulse after creation/reset"),
        Attribute("after", "execution", description="Fires for every later pulse"),
    ),
    state=(
        Attribute("done", "bool", default=False, description="'once' has fired"),
    ),
)


def compute(db):
    if db.inputs.reset == ExecState.ENABLED:
        db.state.done = False
    if db.inputs.execIn == ExecState.ENABLED:
        if db.state.done:
            db.outputs.after = ExecState.ENABLED
        else:
            db.state.done = True
            db.outputs.once = ExecState.ENABLED
