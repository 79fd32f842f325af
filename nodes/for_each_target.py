"""omni.graph.action.ForEachTarget: run loopBody once per target within one tick."""
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState

SPEC = NodeSpec(
    id="omni.graph.action.ForEachTarget",
    version=1,
    description=(
        "An execIn pulse runs loopBody once per prim in targets, in order, all within the same tick "
        "(re-entered after the body's downstream finishes); outputs:target and outputs:arrayIndex hold the "
        "current prim and its index, and keep the last after the loop. 'finished' fires after the last "
        "target (at once when there is none)."),
    categories=("graph:action", "flowControl"),
    ui_name="For Each Target Loop",
    inputs=(
        Attribute("execIn", "execution", description="Starts the loop"),
        Attribute("targets", "target", description="The prims to loop over"),
    ),
    outputs=(
        Attribute("loopBody", "execution", description="Fires once per target"),
        Attribute("target", "target", description="The current target"),
        Attribute("arrayIndex", "int", description="Index of the current target"),
        Attribute("finished", "execution", description="Fires after the last target"),
    ),
    state=(
        Attribute("active", "bool", default=False, description="A loop is running"),
        Attribute("index", "int", default=0, description="Index of the current target"),
    ),
)


def _visit(db, index):
    targets = db.internal.get("targets", ())
    if index < len(targets):
        db.state.active, db.state.index = True, index
        db.outputs.target = (targets[index],)
        db.outputs.arrayIndex = index
        db.outputs.loopBody = ExecState.ENABLED_AND_PUSH
    else:
        db.state.active = False
        db.internal.pop("targets", None)
        db.outputs.finished = ExecState.ENABLED


def compute(db):
    if db.inputs.execIn == ExecState.ENABLED:
        db.internal["targets"] = tuple(db.inputs.targets or ())
        _visit(db, 0)
    elif db.state.active:
        _visit(db, db.state.index + 1)
