"""omni.graph.nodes.ReadSetting: a setting's value from the run's settings store."""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._math import plain
from graphflow_nodes._settings import kit_settings

SPEC = NodeSpec(
    id="omni.graph.nodes.ReadSetting",
    version=1,
    description=(
        "outputs:value = the setting at settingPath, as a WriteSetting of this run wrote it last. graphflow has "
        "no Kit application, so its settings are a store local to the run, empty when it starts: a path no "
        "WriteSetting has written fails the run with a line naming it (Kit's node fails its compute when it "
        "cannot find the setting's type), rather than reading a silent zero."),
    categories=("sceneGraph",),
    ui_name="Read Setting",
    inputs=(
        Attribute("settingPath", "string", default="", description="The setting's path, e.g. /app/mySetting"),
    ),
    outputs=(
        Attribute("value", "any", description="The setting's value"),
    ),
)


def compute(db):
    path = plain(db.inputs.settingPath)
    if not path:
        db.error("inputs:settingPath is empty")
    try:
        db.outputs.value = kit_settings(db).read(path)
    except KeyError as error:
        db.error(str(error.args[0]))
