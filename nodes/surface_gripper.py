"""isaacsim.robot.surface_gripper.SurfaceGripper: open, close or toggle a surface gripper.

Isaac's node (v3): Close beats Open beats Toggle when pulses coincide; Toggle
closes an Open gripper and opens it otherwise (a Closing gripper toggles to
Open); disabled, the node does nothing. Files of typeVersion 1 and 2 load as
this version (v2 had only Toggle, with the same meaning).

Beyond Isaac the node reports the gripper: ``status``, ``isClosed``,
``grippedObjects`` and exec outputs. Grips start and end during physics steps,
so ``gripped`` (an object became held), ``released`` (a grip ended by an open
command) and ``broken`` (a grip ended by a force limit) fire on the compute
that first sees the change, comparing with what the node saw on its previous
compute. To see them on the tick they happen, compute the node every tick:
connect a tick (``OnPlaybackTick.tick``) to ``execIn``, which refreshes the
outputs without commanding the gripper. ``reason`` says why a close failed or a
grip ended (the gripper records it where its status changes).
"""
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState

from ._pick_place import gripper_manager

SPEC = NodeSpec(
    id="isaacsim.robot.surface_gripper.SurfaceGripper",
    version=3,
    compatible_versions=(1, 2),
    aliases=("omni.isaac.surface_gripper.SurfaceGripper",),
    description=(
        "Opens, closes or toggles the IsaacSurfaceGripper prim given in SurfaceGripper (Close beats Open "
        "beats Toggle) and reports its status, gripped objects and grip events."),
    categories=("isaacSurfaceGripper",),
    ui_name="Surface Gripper",
    inputs=(
        Attribute("enabled", "bool", default=True, description="node does not execute if disabled"),
        Attribute("SurfaceGripper", "target", description="The Surface Gripper prim to control"),
        Attribute("Close", "execution", description="Close the gripper"),
        Attribute("Open", "execution", description="Open the gripper"),
        Attribute("Toggle", "execution", description="Toggle the gripper"),
        Attribute("execIn", "execution",
                  description="Refresh the outputs and grip events without a command (connect a tick)"),
    ),
    outputs=(
        Attribute("status", "token", default="Open", allowed_tokens=("Open", "Closing", "Closed"),
                  description="Gripper status after this compute's command"),
        Attribute("isClosed", "bool", description="Status is Closed: every attachment point holds something"),
        Attribute("grippedObjects", "token[]", description="Prim paths of the held objects, sorted"),
        Attribute("reason", "string",
                  description="Why the last close failed or the last grip ended ('' since a close began): no "
                              "surface within reach per attachment point with the nearest hit, retry interval "
                              "elapsed, broken by a force (measured > limit), released by Open"),
        Attribute("execOut", "execution", description="Fires after every enabled compute"),
        Attribute("gripped", "execution", description="Fires when an object has become held since the last compute"),
        Attribute("released", "execution", description="Fires when an open command let go of a held object"),
        Attribute("broken", "execution", description="Fires when a force limit ended the grip on a held object"),
    ),
    state=(
        Attribute("lastGripped", "token[]", description="Objects held at the previous compute"),
        Attribute("lastForceBreaks", "int", default=-1, description="Gripper's force-break count seen last (-1: none yet)"),
        Attribute("lastReleases", "int", default=-1, description="Gripper's release count seen last (-1: none yet)"),
    ),
)


def compute(db):
    if not db.inputs.enabled or not db.inputs.SurfaceGripper:
        return
    path = db.inputs.SurfaceGripper[0]
    manager = gripper_manager(db.world)
    try:
        component = manager.component(path)
    except KeyError:
        db.error(f"inputs:SurfaceGripper: no IsaacSurfaceGripper prim at {path}")
    if db.inputs.Close == ExecState.ENABLED:
        manager.close_gripper(path)
    elif db.inputs.Open == ExecState.ENABLED:
        manager.open_gripper(path)
    elif db.inputs.Toggle == ExecState.ENABLED:
        if component.status.token == "Open":
            manager.close_gripper(path)
        else:
            manager.open_gripper(path)

    gripped = tuple(component.gripped_objects())
    events = component.events
    if db.state.lastForceBreaks >= 0:
        lost = set(db.state.lastGripped) - set(gripped)
        if set(gripped) - set(db.state.lastGripped):
            db.outputs.gripped = ExecState.ENABLED
        if lost and events.releases > db.state.lastReleases:
            db.outputs.released = ExecState.ENABLED
        if lost and events.force_breaks > db.state.lastForceBreaks:
            db.outputs.broken = ExecState.ENABLED
    db.state.lastGripped = gripped
    db.state.lastForceBreaks = events.force_breaks
    db.state.lastReleases = events.releases

    db.outputs.status = component.status.token
    db.outputs.isClosed = component.status.token == "Closed"
    db.outputs.grippedObjects = gripped
    db.outputs.reason = component.reason
    db.outputs.execOut = ExecState.ENABLED
