"""isaacsim.core.nodes.IsaacJointNameResolver: joint names as authored, from their isaac:nameOverride.

An asset may show a joint under another name (the ``isaac:nameOverride``
attribute); ROS messages and controllers then carry that name. The node maps
each given name that is some prim's override back to the prim's own name, and
keeps the others, reading the overrides under the robot prim once (as Isaac).
"""
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState

NAME_OVERRIDE = "isaac:nameOverride"

SPEC = NodeSpec(
    id="isaacsim.core.nodes.IsaacJointNameResolver",
    version=1,
    aliases=("omni.isaac.core_nodes.IsaacJointNameResolver",),
    description=(
        "On execIn, jointNames with each name that is an isaac:nameOverride of a prim under the robot replaced "
        "by that prim's name; the robot (robotPath, else targetPrim) must be or hold an articulation root."),
    categories=("isaacCore",),
    ui_name="Isaac Joint Name Resolver",
    inputs=(
        Attribute("execIn", "execution", description="Resolve the names"),
        Attribute("targetPrim", "target", description="The robot prim (used when robotPath is empty)"),
        Attribute("robotPath", "string", default="", description="The robot prim's path; overrides targetPrim"),
        Attribute("jointNames", "token[]", description="Names to resolve"),
    ),
    outputs=(
        Attribute("execOut", "execution", description="Fires after resolving"),
        Attribute("jointNames", "token[]", description="The names, overrides replaced by prim names"),
        Attribute("robotPath", "string", default="", description="The robot prim's path"),
    ),
)


def compute(db):
    if db.inputs.execIn != ExecState.ENABLED:
        return
    if "overrides" not in db.internal:
        db.internal["robot"], db.internal["overrides"] = _read_overrides(db)
    overrides = db.internal["overrides"]
    db.outputs.jointNames = tuple(overrides.get(name, name) for name in db.inputs.jointNames)
    db.outputs.robotPath = db.internal["robot"]
    db.outputs.execOut = ExecState.ENABLED


def _read_overrides(db) -> tuple[str, dict[str, str]]:
    from pxr import Usd, UsdPhysics

    robot = db.inputs.robotPath or (db.inputs.targetPrim[0] if db.inputs.targetPrim else "")
    if not robot:
        db.error("no articulation root prim: set inputs:robotPath or inputs:targetPrim")
    stage = db.world.stage
    if stage is None:
        db.error("this graph names no stage, so there is no robot to read joint names from")
    start = stage.GetPrimAtPath(robot)
    if not start:
        db.error(f"no prim {robot} on the stage")
    prims = list(Usd.PrimRange(start))
    if not any(prim.HasAPI(UsdPhysics.ArticulationRootAPI) for prim in prims):
        db.error(f"no articulation root at or under {robot}")
    overrides: dict[str, str] = {}
    for prim in prims:
        attribute = prim.GetAttribute(NAME_OVERRIDE)
        override = attribute.Get() if attribute else None
        if override and override != prim.GetName():
            overrides.setdefault(str(override), prim.GetName())
    return robot, overrides
