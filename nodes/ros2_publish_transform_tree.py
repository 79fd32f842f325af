"""isaacsim.ros2.bridge.ROS2PublishTransformTree: the poses of prims as tf2_msgs/TFMessage.

Each target prim is one transform from the parent frame (parentPrim, or world
when none) to the prim; an articulation stands for all its links, each from
the link it hangs on (see _tf). When parentFrames is given (the arrays of
IsaacComputeTransformTree), those transforms are published, their
translations turned from stage units into metres.
"""
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState
from graphflow.world import WorldError

from ._ros2 import common_inputs, header, publish, quaternion, vector
from ._tf import WORLD_FRAME, frames, pose_tree_namer, transform
from .scale_to_from_stage_unit import meters_per_unit

SPEC = NodeSpec(
    id="isaacsim.ros2.bridge.ROS2PublishTransformTree",
    version=1,
    aliases=("omni.isaac.ros2_bridge.ROS2PublishTransformTree",),
    description=(
        "Publishes the world poses of targetPrims (every link of an articulation) relative to parentPrim "
        "(world when unset) as a tf2_msgs/msg/TFMessage on topicName (default tf), frame ids being prim "
        "names (or their isaac:nameOverride); or, when parentFrames is set, the given frames, translations and orientations."),
    categories=("isaacRos2",),
    ui_name="ROS2 Publish Transform Tree",
    inputs=common_inputs("tf", exec_description="Publish") + (
        Attribute("parentPrim", "target", description="Frame the poses are given in (unset: world)"),
        Attribute("targetPrims", "target", description="Prims (or articulations) whose poses to publish"),
        Attribute("timeStamp", "double", default=0.0, description="Message stamp, s"),
        Attribute("staticPublisher", "bool", default=False,
                  description="Publish as static transforms (a latched topic in ROS; the bus keeps the latest)"),
        Attribute("parentFrames", "token[]", description="Parent frame names (from IsaacComputeTransformTree)"),
        Attribute("childFrames", "token[]", description="Child frame names, one per parent frame"),
        Attribute("translations", "double[3][]", description="Translations, stage units, one per parent frame"),
        Attribute("orientations", "double[4][]", description="Rotations (x, y, z, w), one per parent frame"),
    ),
)


def compute(db):
    if db.inputs.execIn != ExecState.ENABLED:
        return
    inputs = db.inputs
    stamp = inputs.timeStamp
    if inputs.parentFrames:
        arrays = (inputs.childFrames, inputs.translations, inputs.orientations)
        if any(len(array) != len(inputs.parentFrames) for array in arrays):
            db.error("inputs:parentFrames, childFrames, translations and orientations must have one entry each")
        units = meters_per_unit(db.world)
        transforms = [_stamped(stamp, parent, child, (tuple(c * units for c in position), rotation))
                      for parent, child, position, rotation in zip(inputs.parentFrames, *arrays)]
    else:
        if not inputs.targetPrims:
            db.error("inputs:targetPrims is not set: no prims to publish")
        parent_prim = inputs.parentPrim[0] if inputs.parentPrim else None
        name_of = pose_tree_namer(db.world.stage)
        root_name = name_of(parent_prim) if parent_prim else WORLD_FRAME
        transforms = []
        try:
            for target in inputs.targetPrims:
                for parent, child in frames(db.world.stage, target):
                    pose = transform(db.world, parent or parent_prim, child)
                    transforms.append(_stamped(stamp, name_of(parent) if parent else root_name, name_of(child), pose))
        except WorldError as error:
            db.error(f"inputs:targetPrims: {error}")
    publish(db, "tf2_msgs/msg/TFMessage", {"transforms": transforms})


def _stamped(stamp: float, parent: str, child: str, pose) -> dict:
    return {"header": header(stamp, parent), "child_frame_id": child,
            "transform": {"translation": vector(pose[0]), "rotation": quaternion(pose[1])}}
