"""omni.graph.action.OnObjectChange: fires when a watched prim property changes.

Headless there is no USD change notice to listen to; the node reads the
property through the world each tick and fires on the tick its value differs
from the tick before (the first reading only sets the baseline). A change
the graph writes with WritePrimAttribute is seen the tick after the write.
"""
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState
from graphflow.world import WorldError

SPEC = NodeSpec(
    id="omni.graph.action.OnObjectChange",
    version=5,
    compatible_versions=(1, 2, 3, 4),
    description=(
        "Fires 'changed' on a tick when the watched property's value differs from the tick before: the "
        "property 'name' of the prim input (or of the prim at 'path'), or the property 'path' names itself "
        "(/World/Cube.physics:mass). propertyName is the watched property's name."),
    categories=("graph:action", "event"),
    ui_name="On USD Object Change",
    inputs=(
        Attribute("name", "token", default="", description="The property to watch on the prim"),
        Attribute("onlyPlayback", "bool", default=True,
                  description="Only fire while playing (graphflow always plays while running)"),
        Attribute("path", "path", default="", description="The prim or property to watch (if prim is unset)"),
        Attribute("prim", "target", description="The prim to watch (takes precedence over path)"),
    ),
    outputs=(
        Attribute("changed", "execution", description="Fires when the property changed"),
        Attribute("propertyName", "token", default="", description="The name of the property that changed"),
    ),
)


def _watched(db) -> tuple[str, str]:
    inputs = db.inputs
    if inputs.prim:
        prim, name = inputs.prim[0], inputs.name
    elif "." in inputs.path.rsplit("/", 1)[-1]:
        prim, name = inputs.path.rsplit(".", 1)
    else:
        prim, name = inputs.path, inputs.name
    if not prim or not name:
        db.error("no property to watch: set inputs:prim (or inputs:path) and inputs:name, or a property path "
                 "in inputs:path; graphflow watches one property, not a whole prim")
    return prim, name


def compute(db):
    prim, name = _watched(db)
    try:
        value = db.world.get_attribute(prim, name)
    except WorldError as error:
        db.error(f"{prim}.{name}: {error}")
    if "value" in db.internal and db.internal["value"] != value:
        db.outputs.propertyName = name
        db.outputs.changed = ExecState.ENABLED
    db.internal["value"] = value
