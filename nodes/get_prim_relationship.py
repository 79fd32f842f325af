"""omni.graph.nodes.GetPrimRelationship: the targets of a prim's relationship."""
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.GetPrimRelationship",
    version=1,
    description="outputs:paths = the prim paths the relationship name of the prim at path targets.",
    categories=("sceneGraph",),
    ui_name="Get Prim Relationship",
    inputs=(
        Attribute("name", "token", default="", description="The relationship's name"),
        Attribute("path", "token", default="", description="The prim's path"),
    ),
    outputs=(
        Attribute("paths", "token[]", description="The targets' paths"),
    ),
)


def compute(db):
    stage = db.world.stage
    if stage is None:
        db.error("this graph names no stage, so there is no relationship to read")
    prim = stage.GetPrimAtPath(db.inputs.path) if db.inputs.path.startswith("/") else None
    if not prim:
        db.error(f"inputs:path: no prim {db.inputs.path!r} on the stage")
    relationship = prim.GetRelationship(db.inputs.name) if db.inputs.name else None
    if not relationship:
        db.error(f"inputs:name: {db.inputs.path} has no relationship {db.inputs.name!r}")
    db.outputs.paths = tuple(str(target) for target in relationship.GetTargets())
