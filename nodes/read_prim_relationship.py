"""omni.graph.nodes.ReadPrimRelationship: the targets of a prim's relationship, as a target."""
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.ReadPrimRelationship",
    version=1,
    description="outputs:value = the prims the relationship name of prim targets, as authored on the stage.",
    categories=("sceneGraph",),
    ui_name="Read Prim Relationship",
    inputs=(
        Attribute("name", "token", default="", description="The relationship's name"),
        Attribute("prim", "target", description="The prim holding the relationship"),
    ),
    outputs=(
        Attribute("value", "target", description="The relationship's targets"),
    ),
)


def compute(db):
    stage = db.world.stage
    if stage is None:
        db.error("this graph names no stage, so there is no relationship to read")
    if len(db.inputs.prim or ()) != 1:
        db.error(f"inputs:prim must name one prim, got {len(db.inputs.prim or ())}")
    path = db.inputs.prim[0]
    prim = stage.GetPrimAtPath(path)
    if not prim:
        db.error(f"inputs:prim: no prim {path!r} on the stage")
    relationship = prim.GetRelationship(db.inputs.name) if db.inputs.name else None
    if not relationship:
        db.error(f"inputs:name: {path} has no relationship {db.inputs.name!r}")
    db.outputs.value = tuple(str(target) for target in relationship.GetTargets())
