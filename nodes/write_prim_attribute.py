"""omni.graph.nodes.WritePrimAttribute: write one attribute of a prim in the world."""
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState
from graphflow.world import WorldError

from .read_prim_attribute import prim_path

SPEC = NodeSpec(
    id="omni.graph.nodes.WritePrimAttribute",
    version=3,
    compatible_versions=(1, 2),
    description=(
        "Writes 'value' to the attribute 'name' of a prim when execIn fires, then fires execOut. "
        "Writable: joint drive targets (drive:linear|angular:physics:targetPosition|targetVelocity, "
        "degrees for angular), body xformOp:translate, xformOp:orient, physics:mass, physics:velocity, "
        "physics:angularVelocity."),
    categories=("sceneGraph",),
    ui_name="Write Prim Attribute",
    inputs=(
        Attribute("execIn", "execution", description="Input execution"),
        Attribute("prim", "target", optional=True, description="The prim to write to (when usePath is false)"),
        Attribute("name", "token", description="The name of the attribute to write"),
        Attribute("value", "any", description="The value to write"),
        Attribute("usePath", "bool", default=False, description="Write the prim at primPath instead of 'prim'"),
        Attribute("primPath", "path", default="", optional=True, description="The prim path used when usePath is true"),
    ),
    outputs=(
        Attribute("execOut", "execution", description="Fires after the value was written"),
    ),
)


def compute(db):
    path = prim_path(db)
    if not db.inputs.name:
        db.error("no attribute name: inputs:name is empty")
    try:
        db.world.set_attribute(path, db.inputs.name, db.inputs.value)
    except WorldError as error:
        db.error(str(error))
    db.outputs.execOut = ExecState.ENABLED
