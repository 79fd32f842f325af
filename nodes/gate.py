"""omni.graph.action.Gate: pass pulses through while open; toggle opens/closes it."""
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState

SPEC = NodeSpec(
    id="omni.graph.action.Gate",
    version=1,
    description=(
        "An 'enter' pulse fires 'exit' while the gate is open. A 'toggle' pulse "
        "flips the gate between open and closed without firing 'exit' (a toggle "
        "and an enter in the same compute: the toggle applies first). The gate "
        "starts closed when startClosed is true, and returns to that on reset."),
    categories=("graph:action", "flowControl"),
    ui_name="Gate",
    inputs=(
        Attribute("enter", "execution", description="Fires 'exit' if the gate is open"),
        Attribute("toggle", "execution", description="Flips the gate open/closed"),
        Attribute("startClosed", "bool", default=False, description="The gate starts closed"),
    ),
    outputs=(
        Attribute("exit", "execution", description="Fires for each 'enter' while open"),
    ),
    state=(
        Attribute("started", "bool", default=False, description="isOpen has been set from startClosed"),
        Attribute("isOpen", "bool", default=True, description="The gate is open"),
    ),
)


def compute(db):
    if not db.state.started:
        db.state.started = True
        db.state.isOpen = not db.inputs.startClosed
    if db.inputs.toggle == ExecState.ENABLED:
        db.state.isOpen = not db.state.isOpen
    if db.inputs.enter == ExecState.ENABLED and db.state.isOpen:
        db.outputs.exit = ExecState.ENABLED
