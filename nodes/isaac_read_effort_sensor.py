"""isaacsim.sensors.physics.IsaacReadEffortSensor: the effort a joint's actuation applies.

prim is the joint (an effort sensor names the joint it measures). The value
is what the joint's drive applied during the last physics step, N m for a
revolute joint and N for a prismatic one: at rest under gravity, the torque
that holds the links beyond the joint up.
"""
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState
from graphflow.world import WorldError

SPEC = NodeSpec(
    id="isaacsim.sensors.physics.IsaacReadEffortSensor",
    version=1,
    aliases=("omni.isaac.sensor.IsaacReadEffortSensor", "omni.isaac.isaac_sensor.IsaacReadEffortSensor"),
    description=(
        "On execIn, the effort (N m or N) the actuation of the joint at prim applied during the last physics "
        "step, and the simulated time. useLatestData, enabled and sensorPeriod are deprecated in Isaac and "
        "ignored there too: the reading is always the latest step's."),
    categories=("isaacPhysicsSensor",),
    ui_name="Isaac Read Effort Node",
    inputs=(
        Attribute("execIn", "execution", description="Read the sensor"),
        Attribute("prim", "target", description="The joint to measure"),
        Attribute("useLatestData", "bool", default=False, description="Deprecated, ignored"),
        Attribute("enabled", "bool", default=True, description="Deprecated, ignored"),
        Attribute("sensorPeriod", "float", default=0.0, description="Deprecated, ignored"),
    ),
    outputs=(
        Attribute("execOut", "execution", description="Fires after the reading"),
        Attribute("sensorTime", "float", default=0.0, description="Simulated time of the reading, s"),
        Attribute("value", "float", default=0.0, description="Effort, N m or N"),
    ),
)


def compute(db):
    if db.inputs.execIn != ExecState.ENABLED:
        return
    if not db.inputs.prim:
        db.error("inputs:prim is not set: no joint to measure")
    joint = db.inputs.prim[0]
    try:
        paths = db.world.joint_paths(joint)
        efforts = db.world.joint_efforts(joint)
    except WorldError as error:
        db.error(f"inputs:prim: {error}")
    if joint not in paths:
        db.error(f"inputs:prim: {joint} is not a movable joint of its articulation")
    db.outputs.value = float(efforts[paths.index(joint)])
    db.outputs.sensorTime = float(db.time)
    db.outputs.execOut = ExecState.ENABLED
