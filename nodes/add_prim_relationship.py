"""omni.graph.action.AddPrimRelationship: add one target to a prim's relationship."""
from graphflow.spec import Attribute, NodeSpec
from graphflow.world import WorldError

from ._stage_edits import on_world

SPEC = NodeSpec(
    id="omni.graph.action.AddPrimRelationship",
    version=1,
    description=(
        "When execIn fires, adds target to the relationship name of the prim at path (creating the "
        "relationship when missing; a target it already has is not added twice). outputs:isSuccessful is "
        "false, with a warning naming the empty input, when path, name or target is empty; a path that is "
        "no prim fails the run. The new target lasts until the world resets and never reaches the file; adding to a physics "
        "relationship (physics:body0/body1, filtered pairs, ...) fails the run naming the prim. Kit's node "
        "has no execOut."),
    categories=("sceneGraph",),
    ui_name="Add Prim Relationship",
    inputs=(
        Attribute("execIn", "execution", description="Input execution"),
        Attribute("name", "token", default="", description="Name of the relationship property to be modified or added"),
        Attribute("path", "path", default="", description="Path of the prim with the relationship property"),
        Attribute("target", "path", default="",
                  description="The target path to be added, which may be a prim, attribute or another relationship"),
    ),
    outputs=(
        Attribute("isSuccessful", "bool", description="Whether the node added the new target to the relationship"),
    ),
)


def compute(db):
    path, name, target = str(db.inputs.path), db.inputs.name, str(db.inputs.target)
    missing = ("inputs:path" if not path else "inputs:name" if not name else "inputs:target" if not target else None)
    if missing is not None:
        db.log(f"{missing} is empty: nothing added", "warning")
        db.outputs.isSuccessful = False
        return
    try:
        current = db.world.relationship_targets(path, name)
    except WorldError:         # no such relationship yet (or no prim, which the write below names)
        current = ()
    if target not in current:
        on_world(db, db.world.set_relationship_targets, path, name, (*current, target))
    db.outputs.isSuccessful = True
