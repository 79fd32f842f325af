"""graphflow.Assert: a check inside the logic; a false condition fails the run.

For what must hold at a point of the routine (e.g. "the gripper is Closed after
the lift"), where a check on the whole run cannot say when. The failure is one
line naming the node, the tick, the simulated time and the message, and the
run ends with exit code 1 (``graphflow run``) or a failed scenario (``graphflow test``).
"""
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState

SPEC = NodeSpec(
    id="graphflow.Assert",
    version=1,
    description=(
        "On an execIn pulse, fails the run when condition is false, with one line naming this node, "
        "the tick, the simulated time and message; fires execOut when it holds."),
    categories=("debug", "flowControl"),
    ui_name="Assert",
    inputs=(
        Attribute("execIn", "execution", description="Check the condition now"),
        Attribute("condition", "bool", default=False, description="Must be true when execIn fires"),
        Attribute("message", "string", default="assertion failed", description="What should have been true"),
    ),
    outputs=(
        Attribute("execOut", "execution", description="Fires when the condition holds"),
    ),
)


def compute(db):
    if db.inputs.execIn != ExecState.ENABLED:
        return
    if not db.inputs.condition:
        db.error(f"assertion failed at tick {db.frame}, t = {db.time:.3f} s: {db.inputs.message}")
    db.outputs.execOut = ExecState.ENABLED
