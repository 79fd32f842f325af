"""omni.graph.action.Multisequence: fire output0..output7 one after another."""
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState

OUTPUT_COUNT = 8

SPEC = NodeSpec(
    id="omni.graph.action.Multisequence",
    version=1,
    description=(
        "For every execIn pulse, fires output0, output1, ... output7 in order, each "
        "only after everything downstream of the previous one has finished "
        "(ENABLED_AND_PUSH re-entry; the last output is plainly enabled). graphflow "
        "declares a fixed 8 outputs; unconnected outputs fire into nothing."),
    categories=("graph:action", "flowControl"),
    ui_name="Sequence",
    inputs=(
        Attribute("execIn", "execution", description="Input execution"),
    ),
    outputs=(
        Attribute("output0", "execution", description="Fires first"),
        Attribute("output1", "execution", description="Fires after everything downstream of output0"),
        Attribute("output2", "execution", description="Fires after everything downstream of output1"),
        Attribute("output3", "execution", description="Fires after everything downstream of output2"),
        Attribute("output4", "execution", description="Fires after everything downstream of output3"),
        Attribute("output5", "execution", description="Fires after everything downstream of output4"),
        Attribute("output6", "execution", description="Fires after everything downstream of output5"),
        Attribute("output7", "execution", description="Fires after everything downstream of output6"),
    ),
    state=(
        Attribute("next", "int", default=-1,
                  description="Index of the output to fire on re-entry (-1 = idle)"),
    ),
)


def _fire(db, index):
    last = index == OUTPUT_COUNT - 1
    setattr(db.outputs, f"output{index}", ExecState.ENABLED if last else ExecState.ENABLED_AND_PUSH)
    db.state.next = -1 if last else index + 1


def compute(db):
    if db.inputs.execIn == ExecState.ENABLED:
        _fire(db, 0)
    elif db.state.next >= 0:
        _fire(db, db.state.next)
