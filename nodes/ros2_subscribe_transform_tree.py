"""isaacsim.ros2.bridge.ROS2SubscribeTransformTree: place free bodies at the poses /tf carries.

frameNamesMap pairs prim paths with frame names ([prim_0, frame_0, prim_1,
frame_1, ...], as Isaac). For each transform of a new tf2_msgs/TFMessage whose
parent and child frames are both mapped, the child prim is placed at the parent
prim's current world pose composed with the transform (translations in metres).
Isaac switches the placed prims' rigid bodies off and moves them kinematically;
graphflow's world cannot switch a body off while running, so a placed free body
gets gravity switched off and its velocity zeroed at each placement: it stays
where /tf puts it unless something pushes it. Articulations cannot be switched
off either: a non-empty articulationRoots, or a mapped prim that is an
articulation's link, fails the run with one line naming it.
"""
from graphflow.poses import IDENTITY_POSE, compose, relative
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState
from graphflow.world import WorldError

from ._ros2 import common_inputs, take

SPEC = NodeSpec(
    id="isaacsim.ros2.bridge.ROS2SubscribeTransformTree",
    version=1,
    aliases=("omni.isaac.ros2_bridge.ROS2SubscribeTransformTree",),
    description=(
        "On execIn, takes the newest tf2_msgs/msg/TFMessage on topicName (default tf) and places each mapped "
        "child prim (a free body) at its mapped parent's world pose composed with the transform; the body's "
        "gravity is switched off and its velocity zeroed, as Isaac's kinematic placement. execOut fires when a "
        "message was taken. Articulations (articulationRoots, or a mapped link) fail the run."),
    categories=("isaacRos2:subscriber",),
    ui_name="ROS2 Subscribe Transform Tree",
    inputs=common_inputs("tf", exec_description="Check for a new message") + (
        Attribute("frameNamesMap", "token[]", description="[prim_path_0, frame_name_0, prim_path_1, ...]"),
        Attribute("articulationRoots", "token[]",
                  description="Articulation roots Isaac switches off (graphflow cannot: must be empty)"),
    ),
    outputs=(
        Attribute("execOut", "execution", description="Fires when a new message was taken"),
    ),
)


def compute(db):
    if db.inputs.execIn != ExecState.ENABLED:
        return
    if db.inputs.articulationRoots:
        db.error(f"inputs:articulationRoots: {db.inputs.articulationRoots[0]}: graphflow's world cannot switch an "
                 "articulation off while running to place its links from /tf")
    prims = db.internal.get("prims")
    if prims is None:
        prims = db.internal["prims"] = _frame_prims(db)
    message = take(db, "tf2_msgs/msg/TFMessage")
    if message is None:
        return
    for stamped in message["transforms"]:
        parent, child = prims.get(stamped["header"]["frame_id"]), prims.get(stamped["child_frame_id"])
        if parent is not None and child is not None:
            _place(db, parent, child, stamped["transform"])
    db.outputs.execOut = ExecState.ENABLED


def _frame_prims(db) -> dict[str, str]:
    """frame name -> prim path, checked as Isaac checks it (even length, no duplicates, prims that exist)."""
    pairs = db.inputs.frameNamesMap
    if len(pairs) % 2:
        db.error("inputs:frameNamesMap must have an even length: [prim_path, frame_name, ...]")
    stage = db.world.stage
    if stage is None and pairs:
        db.error("this graph names no stage, so there are no prims to place")
    prims: dict[str, str] = {}
    for path, frame in zip(pairs[0::2], pairs[1::2]):
        if path in prims.values():
            db.error(f"inputs:frameNamesMap names prim {path} twice")
        if frame in prims:
            db.error(f"inputs:frameNamesMap names frame {frame!r} twice")
        if not stage.GetPrimAtPath(path):
            db.error(f"inputs:frameNamesMap: no prim {path} on the stage")
        prims[frame] = path
    return prims


def _holder_pose(world, path: str):
    """World pose of the prim's USD parent, which its xformOps are relative to (identity at the root)."""
    holder = path.rsplit("/", 1)[0]
    try:
        return world.prim_pose(holder) if holder else IDENTITY_POSE
    except WorldError:
        return IDENTITY_POSE


def _place(db, parent: str, child: str, transform: dict) -> None:
    world = db.world
    translation = tuple(transform["translation"][axis] for axis in "xyz")
    rotation = tuple(transform["rotation"][axis] for axis in "xyzw")
    try:
        if world.body_of(child) != child:
            db.error(f"{child}: not a rigid body, so /tf cannot place it (map the body prim itself)")
        target = compose(world.prim_pose(parent), (translation, rotation))
        local = relative(_holder_pose(world, child), target)
        world.set_attribute(child, "xformOp:translate", local[0])
        world.set_attribute(child, "xformOp:orient", local[1])
        world.set_attribute(child, "physics:velocity", (0.0, 0.0, 0.0))
        world.set_attribute(child, "physics:angularVelocity", (0.0, 0.0, 0.0))
        if world.gravity_enabled(child):
            world.set_gravity_enabled(child, False)
    except WorldError as error:
        db.error(f"{child}: {error}")
