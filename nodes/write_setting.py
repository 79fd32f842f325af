"""omni.graph.nodes.WriteSetting: write a value into the run's settings store."""
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState
from graphflow_nodes._math import plain
from graphflow_nodes._settings import kit_settings

SPEC = NodeSpec(
    id="omni.graph.nodes.WriteSetting",
    version=1,
    description=(
        "On execIn, stores value at settingPath and fires execOut. graphflow's settings are a store local to the "
        "run (no Kit application): ReadSetting reads what was written, in this graph or another of the same "
        "world, from the next compute on; the store empties when the run restarts. A setting keeps the type it "
        "was first written with (bool, int, float, string, or an array of one of them); writing another type "
        "fails the run, as Kit refuses a value whose type does not match the setting's."),
    categories=("sceneGraph",),
    ui_name="Write Setting",
    inputs=(
        Attribute("execIn", "execution", description="Writes the setting"),
        Attribute("settingPath", "string", default="", description="The setting's path, e.g. /app/mySetting"),
        Attribute("value", "any", description="The value to write"),
    ),
    outputs=(
        Attribute("execOut", "execution", description="Fires after the setting is written"),
    ),
)


def compute(db):
    if db.inputs.execIn != ExecState.ENABLED:
        return
    path, value = plain(db.inputs.settingPath), plain(db.inputs.value)
    if not path:
        db.error("inputs:settingPath is empty")
    if value is None:
        db.error("inputs:value has no value")
    try:
        kit_settings(db).write(path, value)
    except ValueError as error:
        db.error(str(error))
    db.outputs.execOut = ExecState.ENABLED
