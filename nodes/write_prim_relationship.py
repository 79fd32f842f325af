"""omni.graph.nodes.WritePrimRelationship: set the targets of a prim's relationship."""
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState

from ._stage_edits import LAYER_IDENTIFIER, on_world, target_prim

SPEC = NodeSpec(
    id="omni.graph.nodes.WritePrimRelationship",
    version=2,
    compatible_versions=(1,),
    description=(
        "When execIn fires, makes the relationship name of prim (created when missing) target exactly "
        "value, then fires execOut. ReadPrimRelationship and the stage see the new targets until the world "
        "resets; the file never does, so usdWriteBack changes nothing. A physics relationship (a joint's "
        "physics:body0/body1, filtered pairs, ...) is composed once at load: writing one fails the run "
        "naming the prim."),
    categories=("sceneGraph",),
    ui_name="Write Prim Relationship",
    inputs=(
        Attribute("execIn", "execution", description="Input execution"),
        LAYER_IDENTIFIER,
        Attribute("name", "token", default="", description="The name of the relationship to write"),
        Attribute("prim", "target", description="The prim to write the relationship to"),
        Attribute("usdWriteBack", "bool", default=True,
                  description="Kit: write to USD or keep the value in Fabric only (no effect: the stage is the one copy)"),
        Attribute("value", "target", optional=True,
                  description="The target(s) to write to the relationship (none: the relationship targets nothing)"),
    ),
    outputs=(
        Attribute("execOut", "execution", description="Fires after the relationship was written"),
    ),
)


def compute(db):
    if not db.inputs.name:
        db.error("no relationship name: inputs:name is empty")
    on_world(db, db.world.set_relationship_targets, target_prim(db), db.inputs.name, tuple(db.inputs.value or ()))
    db.outputs.execOut = ExecState.ENABLED
