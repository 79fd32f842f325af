"""graphflow.ReadSurfaceGripperState: a surface gripper's status, pulled whenever a consumer computes.

The SurfaceGripper node reports its outputs only when one of its exec inputs
fires; graphs that command the gripper some other way (the pick-and-place
controllers do it through the gripper manager) read the state with this pure node.
"""
from graphflow.spec import Attribute, NodeSpec

from ._pick_place import gripper_manager

SPEC = NodeSpec(
    id="graphflow.ReadSurfaceGripperState",
    version=1,
    description=(
        "The status (Open, Closing, Closed) and gripped objects of the IsaacSurfaceGripper at "
        "gripperPrim, from the world's surface-gripper manager. A prim that is no surface "
        "gripper is a run-time error."),
    categories=("isaacSurfaceGripper",),
    ui_name="Read Surface Gripper State",
    inputs=(
        Attribute("gripperPrim", "target", description="The IsaacSurfaceGripper prim"),
    ),
    outputs=(
        Attribute("status", "token", allowed_tokens=("Open", "Closing", "Closed"), description="Gripper status"),
        Attribute("isClosed", "bool", description="Status is Closed (every attachment point holds)"),
        Attribute("grippedObjects", "token[]", description="Prim paths of the held objects, sorted"),
    ),
)


def compute(db):
    if not db.inputs.gripperPrim:
        db.error("inputs:gripperPrim: no surface gripper given")
    path = db.inputs.gripperPrim[0]
    try:
        component = gripper_manager(db.world).component(path)
    except KeyError:
        db.error(f"inputs:gripperPrim: no surface gripper at {path}")
    db.outputs.status = component.status.token
    db.outputs.isClosed = component.status.token == "Closed"
    db.outputs.grippedObjects = tuple(component.gripped_objects())
