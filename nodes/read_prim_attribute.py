"""omni.graph.nodes.ReadPrimAttribute: read one attribute of a prim from the world."""
from graphflow.spec import Attribute, NodeSpec
from graphflow.world import WorldError

SPEC = NodeSpec(
    id="omni.graph.nodes.ReadPrimAttribute",
    version=3,
    compatible_versions=(1, 2),
    description=(
        "Reads the attribute 'name' of a prim: live physics values (drive targets, joint state, body "
        "pose, mass, velocity; joint limits) come from the world, any other authored attribute from the "
        "stage. Values use USD units (degrees for angular drive targets and limits); quaternions are "
        "(x, y, z, w)."),
    categories=("sceneGraph",),
    ui_name="Read Prim Attribute",
    inputs=(
        Attribute("prim", "target", optional=True, description="The prim to read from (when usePath is false)"),
        Attribute("name", "token", description="The name of the attribute to read"),
        Attribute("usePath", "bool", default=False, description="Read the prim at primPath instead of 'prim'"),
        Attribute("primPath", "path", default="", optional=True, description="The prim path used when usePath is true"),
    ),
    outputs=(
        Attribute("value", "any", description="The attribute value"),
    ),
)


def prim_path(db) -> str:
    """The prim a node addresses: primPath when usePath is set, else the first 'prim' target."""
    if db.inputs.usePath:
        path = db.inputs.primPath
    else:
        path = db.inputs.prim[0] if db.inputs.prim else ""
    if not path:
        db.error("no prim given (set 'prim', or 'usePath' and 'primPath')")
    return path


def compute(db):
    path = prim_path(db)
    if not db.inputs.name:
        db.error("no attribute name: inputs:name is empty")
    try:
        db.outputs.value = db.world.get_attribute(path, db.inputs.name)
    except WorldError as error:
        db.error(str(error))
