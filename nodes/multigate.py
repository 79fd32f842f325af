"""omni.graph.action.Multigate: each execIn pulse fires the next output in turn, 0 -> 1 -> ... -> 0."""
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState

OUTPUT_COUNT = 8

SPEC = NodeSpec(
    id="omni.graph.action.Multigate",
    version=2,
    compatible_versions=(1,),
    description=(
        "Each execIn pulse fires one output, cycling output0, output1, ... back to output0. A Kit node has as "
        "many outputs as its author added; graphflow declares output0..output7 and cycles through as many as "
        "reach the highest connected one (output0..output2 connected: 0, 1, 2, 0, ...). A reset pulse makes "
        "the next execIn fire output0 again, without firing anything itself."),
    categories=("graph:action", "flowControl"),
    ui_name="Multigate",
    inputs=(
        Attribute("execIn", "execution", description="Fires the current output, then moves to the next"),
        Attribute("reset", "execution", description="The next execIn fires output0"),
    ),
    outputs=tuple(Attribute(f"output{index}", "execution", description=f"Fires on execIn pulse {index} of each cycle")
                  for index in range(OUTPUT_COUNT)),
    state=(
        Attribute("current", "int", default=0, description="Index of the output the next execIn fires"),
    ),
)


def compute(db):
    if db.inputs.reset == ExecState.ENABLED:
        db.state.current = 0
    if db.inputs.execIn != ExecState.ENABLED:
        return
    connected = [int(name[len("output"):]) for name in db.connected_exec_outputs]
    cycle = max(connected, default=0) + 1
    current = db.state.current % cycle
    setattr(db.outputs, f"output{current}", ExecState.ENABLED)
    db.state.current = (current + 1) % cycle
