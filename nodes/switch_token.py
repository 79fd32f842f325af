"""omni.graph.action.SwitchToken: continue down the output whose branch token matches value.

Kit gives the node dynamic inputs branchX and outputs outputX; graphflow
declares eight fixed pairs, branch0..branch7 and output0..output7. When several
branches hold the value the lowest index fires (Kit leaves the choice open);
no match fires nothing.
"""
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState

BRANCHES = 8

SPEC = NodeSpec(
    id="omni.graph.action.SwitchToken",
    version=1,
    description=(
        "On execIn, fires outputN for the first branchN (N = 0..7) equal to value; nothing when none matches."),
    categories=("graph:action", "flowControl"),
    ui_name="Switch On Token",
    inputs=(
        Attribute("execIn", "execution", description="Input execution"),
        Attribute("value", "token", default="", description="The token to switch on"),
    ) + tuple(Attribute(f"branch{n}", "token", default="", optional=True, description=f"Token that fires output{n}")
              for n in range(BRANCHES)),
    outputs=tuple(Attribute(f"output{n}", "execution", description=f"Fires when value equals branch{n}")
                  for n in range(BRANCHES)),
)


def compute(db):
    if db.inputs.execIn != ExecState.ENABLED:
        return
    value = db.inputs.value
    for n in range(BRANCHES):
        branch = getattr(db.inputs, f"branch{n}")
        if branch and branch == value:
            setattr(db.outputs, f"output{n}", ExecState.ENABLED)
            return
