"""isaacsim.core.nodes.IsaacComputeTransformTree: a transform tree as arrays, for ROS2PublishTransformTree.

The same frames as ROS2PublishTransformTree publishes (each target prim from
parentPrim or world, an articulation as its link tree: see _tf), as parallel
arrays; translations in stage units, as Isaac gives them.
"""
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState
from graphflow.world import WorldError

from ._tf import WORLD_FRAME, compute_tree_names, frame_name, frames, transform
from .scale_to_from_stage_unit import meters_per_unit

SPEC = NodeSpec(
    id="isaacsim.core.nodes.IsaacComputeTransformTree",
    version=1,
    aliases=("omni.isaac.core_nodes.IsaacComputeTransformTree",),
    description=(
        "On execIn, the transforms of targetPrims (every link of an articulation) relative to parentPrim "
        "(world when unset): parent and child frame names (prim names or their isaac:nameOverride), "
        "translations (stage units) and "
        "orientations (x, y, z, w)."),
    categories=("isaacCore",),
    ui_name="Isaac Compute Transform Tree",
    inputs=(
        Attribute("execIn", "execution", description="Compute the tree"),
        Attribute("parentPrim", "target", description="Frame the transforms are given in (unset: world)"),
        Attribute("targetPrims", "target", description="Prims (or articulations) to compute transforms for"),
    ),
    outputs=(
        Attribute("execOut", "execution", description="Fires after the tree was computed"),
        Attribute("parentFrames", "token[]", description="Parent frame name per transform"),
        Attribute("childFrames", "token[]", description="Child frame name per transform"),
        Attribute("translations", "double[3][]", description="Translation per transform, stage units"),
        Attribute("orientations", "double[4][]", description="Rotation per transform (x, y, z, w)"),
    ),
)


def compute(db):
    if db.inputs.execIn != ExecState.ENABLED:
        return
    if not db.inputs.targetPrims:
        db.error("inputs:targetPrims is not set: no prims to compute")
    parent_prim = db.inputs.parentPrim[0] if db.inputs.parentPrim else None
    stage = db.world.stage
    root_name = frame_name(stage, parent_prim) if parent_prim else WORLD_FRAME
    units = meters_per_unit(db.world)
    pairs = [pair for target in db.inputs.targetPrims for pair in frames(stage, target)]
    names = dict(zip((child for _, child in pairs), compute_tree_names(stage, [child for _, child in pairs])))
    parents, children, translations, orientations = [], [], [], []
    try:
        for parent, child in pairs:
            position, orientation = transform(db.world, parent or parent_prim, child)
            parents.append((names.get(parent) or frame_name(stage, parent)) if parent else root_name)
            children.append(names[child])
            translations.append(tuple(c / units for c in position))
            orientations.append(tuple(float(c) for c in orientation))
    except WorldError as error:
        db.error(f"inputs:targetPrims: {error}")
    db.outputs.parentFrames, db.outputs.childFrames = tuple(parents), tuple(children)
    db.outputs.translations, db.outputs.orientations = tuple(translations), tuple(orientations)
    db.outputs.execOut = ExecState.ENABLED
